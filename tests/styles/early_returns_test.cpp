// early_returns (tests/styles/): every generated function of each kernel
// checked on arrays of exactly n values (one_to_one_cases.hpp); the generator
// of session 23 refused them all.
#include "dpgen/annotate.hpp"
#include "early_returns_adjoint.hpp"
#include "early_returns_kernels.hpp"
#include "early_returns_tangent.hpp"
#include "one_to_one_cases.hpp"

TEST_CASE("styles: early returns of helpers and lambdas") {
  dpgen_test::check_cases({DPGEN_CASE(flux_early), DPGEN_CASE(slopes_early),
                           DPGEN_CASE(nested_early), DPGEN_CASE(forwarded_early),
                           DPGEN_CASE(guarded_early), DPGEN_CASE(store_early),
                           DPGEN_CASE(constexpr_early), DPGEN_CASE(lambda_sets_after),
                           DPGEN_CASE(lambda_arm_sets), DPGEN_CASE(lambda_helper_sets)});
}
