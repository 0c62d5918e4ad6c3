// doctest main for the kernel adjoint tests. In the test executables of the
// build (which define DPGEN_TEST_CHECKER_COMPILED_ONCE) also the one compiled
// copy of the adjoint checker (tests/support/adjoint_check.hpp) that their test
// files share; the corpus scripts compile it alone, as a plain doctest main.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include <doctest/doctest.h>

#ifdef DPGEN_TEST_CHECKER_COMPILED_ONCE
#include "support/adjoint_check.hpp"

template class dpgen_test::Checker<float>;
template class dpgen_test::Checker<double>;
#endif
