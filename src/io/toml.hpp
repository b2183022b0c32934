#pragma once
/// @file
/// toml++ as feran's readers include it: every source that includes toml++ includes
/// this header, so that its inline parser is the same in each (one definition).
///
/// toml++ 3.3.0 (Debian 12's) checks its own assumptions about what its look-ahead
/// saw with TOML_ASSERT, and some of them fail on malformed text (fuzzing found a
/// date followed by `T` and no digit, `a = [1, }`). In a build without assertions
/// (a release build) nothing is checked and the parser goes on to a located syntax
/// error; in a build with them (the test suite's sanitizer pass, the fuzzing build)
/// the program aborted instead. They are off here in every build, so that each build
/// parses as the release build does, and the sanitizers (AddressSanitizer,
/// UndefinedBehaviorSanitizer) judge the code that follows. What is undefined
/// behaviour in every build (toml++'s TOML_UNREACHABLE) the model reader refuses
/// before parsing (io/model_reader.cpp, check_before_parsing; docs/fuzzing.md).
#define TOML_ASSERT(expr) static_assert(true)
#include <toml++/toml.h>
