// Constants of a code's own header (tests/generator/macro_literal.cpp).
#define CFL_COEF 0.25
#define HALF(x) (0.5 * (x))
