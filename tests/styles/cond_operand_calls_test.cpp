// cond_operand_calls (tests/styles/): every generated function of each
// kernel checked on arrays of exactly n values (one_to_one_cases.hpp); the
// generator of session 23 read a[-1] in all of them but buffer_arm, which it
// refused.
#include "cond_operand_calls_adjoint.hpp"
#include "cond_operand_calls_kernels.hpp"
#include "cond_operand_calls_tangent.hpp"
#include "dpgen/annotate.hpp"
#include "one_to_one_cases.hpp"

TEST_CASE("styles: calls in conditional operands") {
  dpgen_test::check_cases({DPGEN_CASE(sq_left), DPGEN_CASE(lambda_right), DPGEN_CASE(index_lambda),
                           DPGEN_CASE(and_guard), DPGEN_CASE(or_guard), DPGEN_CASE(last_value),
                           DPGEN_CASE(nested_select), DPGEN_CASE_NO_PARALLEL(buffer_arm),
                           DPGEN_CASE(c89_limited)});
}
