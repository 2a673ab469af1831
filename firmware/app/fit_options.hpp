// The options `kerf fit` and `kerf plan` both take, declared once so that
// their help reads the same.
#pragma once

#include <string>

namespace CLI {
class App;
class Option;
}

namespace kerf::app {

// A command that fits points within --tol: the subcommand, --tol first.
CLI::App* add_fitting_command(CLI::App& app, const std::string& name, const std::string& help,
                              std::string& tol);
CLI::Option* add_numeric_option(CLI::App* command, std::string& numeric);
CLI::Option* add_points_file(CLI::App* command, std::string& file);

}  // namespace kerf::app
