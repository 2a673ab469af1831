// toml++ as every config source file includes it. Its ABI depends on these
// settings, so they live in this one place: a TU that saw different values
// would break the one-definition rule.
// - TOML_EXCEPTIONS 0: parse() returns a toml::parse_result to test.
// - TOML_HEADER_ONLY 0: the parser is compiled once, in tomlpp.cpp, not in
//   every file that includes this.
#pragma once

#define TOML_EXCEPTIONS 0
#define TOML_HEADER_ONLY 0
#include <toml++/toml.h>
