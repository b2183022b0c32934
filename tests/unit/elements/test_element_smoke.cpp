#include <gtest/gtest.h>
#include <feran/elements/timoshenko_beam.hpp>
TEST(Smoke, Builds) { SUCCEED(); }
