// doctest main for the kernel adjoint tests, and the one compiled copy of the adjoint checker
// (tests/support/adjoint_check.hpp) that their test files share: the executables that link this
// file define DPGEN_TEST_CHECKER_COMPILED_ONCE.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#include "support/adjoint_check.hpp"

#ifndef DPGEN_TEST_CHECKER_COMPILED_ONCE
#error "link tests/kernels/main.cpp only into targets that define DPGEN_TEST_CHECKER_COMPILED_ONCE"
#endif

template class dpgen_test::Checker<float>;
template class dpgen_test::Checker<double>;
