#include "support/adjoint_check.hpp"
#include "dpgen/annotate.hpp"
#include "a42_null_adj_adjoint.hpp"
#include <vector>
TEST_CASE("adversary: a42_null_adj") {
  for (int n : {0, 1, 2, 3, 5, 9}) {
    CAPTURE(n);
    std::vector<double> a(n), b(n), sw(n), so(n);
    for (int i = 0; i < n; ++i) { a[i] = 0.3 + i; b[i] = 1.1 - 0.2 * i; sw[i] = 0.7 * i - 1; so[i] = 0.5 + 0.1 * i; }
    std::vector<double> aa(n, 0.5), ba(n, 0.25), aa2(n, 0.5), ba2(n, 0.25);
    a42_null_adj_adjoint(a.data(), aa.data(), b.data(), ba.data(), sw.data(), so.data(), n);
    a42_null_adj_adjoint(a.data(), aa2.data(), b.data(), nullptr, sw.data(), so.data(), n);
    std::vector<double> aa3(n, 0.5), ba3(n, 0.25);
    a42_null_adj_adjoint(a.data(), nullptr, b.data(), ba3.data(), sw.data(), so.data(), n);
    for (int i = 0; i < n; ++i) { CHECK(aa[i] == aa2[i]); CHECK(ba[i] == ba3[i]); }
  }
}
