#include "app/fit_options.hpp"

#include <CLI/CLI.hpp>

namespace kerf::app {

CLI::App* add_fitting_command(CLI::App& app, const std::string& name, const std::string& help,
                              std::string& tol) {
  CLI::App* command = app.add_subcommand(name, help);
  command->add_option("--tol", tol, "Largest distance of a point from its piece (> 0)")->type_name("EPS");
  return command;
}

CLI::Option* add_numeric_option(CLI::App* command, std::string& numeric) {
  return command
      ->add_option("--numeric", numeric,
                   "Scalar type of the fit: double, or fixed (Q31.32, what a core without an FPU "
                   "runs; vertex and band criteria)")
      ->type_name("TYPE")
      ->capture_default_str();
}

CLI::Option* add_points_file(CLI::App* command, std::string& file) {
  return command->add_option("file", file, "Point file, one \"x y\" per line; - for stdin")
      ->type_name("FILE|-")
      ->required();
}

}  // namespace kerf::app
