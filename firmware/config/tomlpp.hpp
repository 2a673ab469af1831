// toml++ as every config source file includes it. toml++ is header-only and
// its ABI depends on TOML_EXCEPTIONS, so the setting lives in this one place:
// a TU that saw a different value would break the one-definition rule.
// Without exceptions, parse() returns a toml::parse_result to test.
#pragma once

#define TOML_EXCEPTIONS 0
#include <toml++/toml.h>
