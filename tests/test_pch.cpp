// rupture/tests/test_pch.cpp
// The object that compiles tests/test_pch.hpp into the precompiled header the tests reuse.
#include "test_pch.hpp"
