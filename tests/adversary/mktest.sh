#!/usr/bin/env bash
# mktest.sh <name> <in sizes> <out sizes> <n values> [int type]
# Writes <name>_test.cpp for a kernel name(const double* in..., double* out..., <int type> n):
# sizes are C++ expressions in n, comma separated; checks adjoint, tangent and the checked entry.
name=$1; ins=$2; outs=$3; ns=$4; ity=${5:-int}
IFS=, read -ra I <<<"$ins"; IFS=, read -ra O <<<"$outs"
decl=(); fw=(); adj=(); tan=(); chk=()
for k in "${!I[@]}"; do decl+=("const double*"); fw+=("in[$k]"); adj+=("in[$k]" "adj[$k]"); tan+=("in[$k]" "dir[$k]"); chk+=("in[$k]" "in_n[$k]" "adj[$k]" "in_n[$k]"); done
for k in "${!O[@]}"; do decl+=("double*"); fw+=("out[$k]"); adj+=("seed[$k]"); tan+=("out[$k]" "od[$k]"); chk+=("seed[$k]" "out_n[$k]"); done
j(){ local IFS=','; echo "$*" | sed 's/,/, /g'; }
ISZ=$(for s in "${I[@]}"; do printf 'ADV_SZ(%s),' "$s"; done); OSZ=$(for s in "${O[@]}"; do printf 'ADV_SZ(%s),' "$s"; done)
cat > "${name}_test.cpp" <<EOT
// ${name} (tests/adversary/): see ${name}.cpp; sizes n in {${ns}}.
#include "adv.hpp"
#include "${name}_adjoint.hpp"
#include "${name}_tangent.hpp"
void ${name}($(j "${decl[@]}"), ${ity} n);
TEST_CASE("adversary: ${name}") {
  for (${ity} n : {${ns}}) {
    CAPTURE(n);
    dpgen_test::Problem<double> p;
    p.in_sizes = {${ISZ%,}};
    p.out_sizes = {${OSZ%,}};
    p.forward = [&](auto in, auto out) { ${name}($(j "${fw[@]}"), n); };
    p.adjoint = [&](auto in, auto adj, auto seed) { ${name}_adjoint($(j "${adj[@]}"), n); };
    p.tangent = [&](auto in, auto dir, auto out, auto od) { ${name}_tangent($(j "${tan[@]}"), n); };
    p.checked = [&](auto in, auto adj, auto seed, auto in_n, auto out_n) {
      ${name}_adjoint_checked($(j "${chk[@]}"), n);
    };
    dpgen_test::check_adjoint(p);
  }
}
EOT
