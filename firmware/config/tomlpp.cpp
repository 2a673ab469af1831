// toml++'s implementation, compiled once (see tomlpp.hpp).
#define TOML_IMPLEMENTATION
#include "config/tomlpp.hpp"
