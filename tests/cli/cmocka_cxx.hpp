// cmocka from C++: the headers it needs first, and its functions declared extern "C" (cmocka 1.1
// does not do it itself).
#pragma once

#include <csetjmp>
#include <cstdarg>
#include <cstddef>
#include <cstdint>
#include <fstream>  // before cmocka.h, whose fail() macro breaks std::ios::fail
#include <sstream>
#include <string>

extern "C" {
#include <cmocka.h>
}
