// rupture/tests/test_pch.hpp
// The headers most unit tests include (GoogleTest, the standard library, the case reader and the
// solver's state and step), precompiled once for every rupture_test target (tests/CMakeLists.txt):
// each test's own code then parses in about two thirds of the time (test_loads.cpp: 3.4 s against
// 4.7 s, g++ 12 -O1). Only what many tests include belongs here: a test that does not use a
// header merely parses it, and a change to one of these rebuilds every test.
#pragma once
#include <gtest/gtest.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "input/case_toml.hpp"
#include "solver/state.hpp"
#include "solver/step.hpp"
