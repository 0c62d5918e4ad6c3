// Unit tests of the generator's phases, one at a time, on tiny kernels held in
// memory: lower (source -> IR), derive (partials), schedule (gather groups,
// blocks, scatter units) and emit (printing). The golden and diagnostic lit
// tests check what the tool writes as a whole; these check what each phase
// hands to the next, so a change that breaks one phase fails here by name.
#define DOCTEST_CONFIG_IMPLEMENT_WITH_MAIN
#include "lib/derive.hpp"
#include "lib/emit.hpp"
#include "lib/emit_file.hpp"
#include "lib/find.hpp"
#include "lib/hoist.hpp"
#include "lib/loop_plan.hpp"
#include "lib/ops.hpp"
#include "lib/print.hpp"
#include "lib/schedule.hpp"
#include "lib/share.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

using namespace dpgen;

std::string annotate_header() {
  std::ifstream f(DPGEN_ANNOTATE_HPP);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

// Lowers `code` (a file that includes dpgen/annotate.hpp); diagnostics are
// dropped, the result says whether the file was accepted.
bool lower(const std::string& code, std::vector<Kernel>& kernels) {
  FrontendOptions o;
  o.resource_dir = DPGEN_CLANG_RESOURCE_DIR;
  o.driver = DPGEN_CLANG_DRIVER;
  o.quiet = true;
  return lower_code("#include \"dpgen/annotate.hpp\"\n" + code, "unit.cpp", o, kernels,
                    {{"dpgen/annotate.hpp", annotate_header()}});
}

Kernel lower_one(const std::string& code) {
  std::vector<Kernel> ks;
  REQUIRE(lower(code, ks));
  REQUIRE(ks.size() == 1);
  return ks.front();
}

// Phases 3 and 4: the partials, then the schedule that looks them up.
AdjointPlan schedule_of(const Kernel& k) {
  Partials partials = derive(k);
  return schedule(k, partials);
}

// The shifts of a gather group's blocks in counter `v`, as "v:-1" strings
// (a block without an entry for `v` has shift 0), sorted.
std::vector<std::string> shifts(const GatherGroup& g, const std::string& v) {
  std::vector<std::string> out;
  for (const auto& b : g.blocks) {
    auto it = b.shift.find(v);
    out.push_back(v + ":" + (it == b.shift.end() ? std::string("0") : it->second.str()));
  }
  std::sort(out.begin(), out.end());
  return out;
}

const char* kUpwind = R"(
DPGEN_KERNEL void up(DPGEN_IN const double* d, DPGEN_OUT double* out, int n, double c) {
  for (int i = 1; i < n - 1; ++i)
    out[i] = d[i] - c * (d[i] - d[i - 1]) + 0.5 * d[i + 1] * d[i + 1];
}
)";

} // namespace

TEST_CASE("lower: parameters, one nest, its loop bounds and the store") {
  const Kernel k = lower_one(kUpwind);
  CHECK(k.name == "up");
  REQUIRE(k.params.size() == 4);
  CHECK(k.params[0].kind == ParamKind::In);
  CHECK(k.params[1].kind == ParamKind::Out);
  CHECK(k.params[2].kind == ParamKind::Scalar);
  CHECK(k.params[3].kind == ParamKind::Scalar);
  CHECK(k.params[3].elem == Type::Double);
  REQUIRE(k.nests.size() == 1);
  const Nest& nest = k.nests.front();
  REQUIRE(nest.loops.size() == 1);
  CHECK(print(nest.loops[0].lo) == "1");
  CHECK(print(nest.loops[0].hi) == "n - 1");
  REQUIRE(nest.stores.size() == 1);
  const Store& s = nest.stores.front();
  CHECK(s.array == "out");
  CHECK(print(s.index) == nest.loops[0].var);
  CHECK_FALSE(s.accumulate);
  CHECK(s.pos.line == 5); // the include line and an empty line come first
  // Three distinct cells of d are read.
  std::set<std::string> cells;
  for (const auto& r : reads_in(s.value))
    cells.insert(print(r.read->ops[0]));
  CHECK(cells.size() == 3);
}

TEST_CASE("lower: a C89 counter declared before its loop gives the same IR as one declared in it") {
  const Kernel a = lower_one(R"(
DPGEN_KERNEL void k(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; i++) b[i] = 3.0 * a[i];
})");
  const Kernel c89 = lower_one(R"(
DPGEN_KERNEL void k(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  int i;
  for (i = 0; i < n; i++) b[i] = 3.0 * a[i];
})");
  REQUIRE(a.nests.size() == 1);
  REQUIRE(c89.nests.size() == 1);
  CHECK(print(a.nests[0].loops[0].hi) == print(c89.nests[0].loops[0].hi));
  CHECK(print(a.nests[0].stores[0].value) == print(c89.nests[0].stores[0].value));
  CHECK(print(a.nests[0].stores[0].index) == print(c89.nests[0].stores[0].index));
}

TEST_CASE("lower: two nests stay two nests, each with its own bounds (issue 9, defect 1)") {
  const Kernel k = lower_one(R"(
DPGEN_KERNEL void two(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* x,
                      DPGEN_OUT double* y, int m, int n) {
  for (int k = 0; k < m; k++) for (int j = 0; j < n + 1; j++) x[k * (n + 2) + j] = 2.0 * a[k * (n + 2) + j];
  for (int k = 0; k < m + 1; k++) for (int j = 0; j < n; j++) y[k * (n + 2) + j] = 3.0 * b[k * (n + 2) + j];
})");
  REQUIRE(k.nests.size() == 2);
  CHECK(print(k.nests[0].loops[0].hi) == "m");
  CHECK(print(k.nests[0].loops[1].hi) == "n + 1");
  CHECK(print(k.nests[1].loops[0].hi) == "m + 1");
  CHECK(print(k.nests[1].loops[1].hi) == "n");
  CHECK(k.nests[0].stores[0].array == "x");
  CHECK(k.nests[1].stores[0].array == "y");
}

TEST_CASE("lower: '+=' into an output is an accumulating store; a leading guard is on its path") {
  const Kernel k = lower_one(R"(
DPGEN_KERNEL void red(DPGEN_IN const double* a, DPGEN_OUT double* s, int n) {
  if (n < 2) return;
  for (int i = 0; i < n; ++i) s[0] += a[i] * a[i];
})");
  REQUIRE(k.nests.size() == 1);
  const Store& s = k.nests[0].stores[0];
  CHECK(s.accumulate);
  // `if (n < 2) return;` before the loop: the store runs where !(n < 2).
  REQUIRE(s.path.size() == 1);
  CHECK_FALSE(s.path[0].positive);
  CHECK(print(s.path[0].cond) == "n < 2");
}

TEST_CASE("lower: kernels outside the subset are rejected, and no kernel is returned") {
  std::vector<Kernel> ks;
  CHECK_FALSE(lower(R"(
DPGEN_KERNEL void gs(DPGEN_OUT double* u, DPGEN_IN const double* f, int n) {
  for (int i = 1; i < n; ++i) u[i] = u[i - 1] + f[i];
})",
                    ks));
  ks.clear();
  CHECK_FALSE(lower(R"(
DPGEN_KERNEL void brk(DPGEN_IN const double* a, DPGEN_OUT double* b, int n) {
  for (int i = 0; i < n; ++i) { if (a[i] > 1) break; b[i] = a[i]; }
})",
                    ks));
  ks.clear();
  CHECK_FALSE(lower("int f(int x) { return x; }\n", ks)); // a file without any kernel
}

TEST_CASE("derive: partials of a store's value w.r.t. one read") {
  const Kernel k = lower_one(R"(
DPGEN_KERNEL void sq(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) o[i] = a[i] * a[i] + 2.0 * b[i];
})");
  const Store& s = k.nests[0].stores[0];
  std::set<const Expr*> a_reads, b_reads;
  for (const auto& r : reads_in(s.value))
    (r.read->name == "a" ? a_reads : b_reads).insert(r.read);
  REQUIRE(a_reads.size() == 2); // both occurrences of a[i]: one cell
  REQUIRE(b_reads.size() == 1);
  DeriveNames names;
  const ExprP da = derivative(s.value, a_reads, names);
  const ExprP db = derivative(s.value, b_reads, names);
  REQUIRE(!is_zero(da));
  REQUIRE(!is_zero(db));
  CHECK(print(db) == "2.0");
  // d(a*a)/da = a + a (one term per occurrence), in whatever order the rule writes it.
  const std::string pa = print(da);
  CHECK(pa.find("a[i]") != std::string::npos);
  CHECK(pa.find("b[") == std::string::npos);
  // A read the value does not depend on has an exactly zero partial.
  DeriveNames fresh;
  const Store& same = k.nests[0].stores[0];
  std::set<const Expr*> none;
  CHECK(is_zero(derivative(same.value, none, fresh)));
}

TEST_CASE("derive: the phase computes each partial once; the schedule's lookups return it") {
  const Kernel k = lower_one(kUpwind);
  Partials partials = derive(k);
  const Store& s = k.nests[0].stores[0];
  for (const auto& r : reads_in(s.value)) {
    const ExprP& first = partials.of(s, {r.read});
    const ExprP& second = partials.of(s, {r.read});
    CHECK(&first == &second); // the same table entry: not derived again
    REQUIRE(first != nullptr);
  }
}

TEST_CASE("schedule: a three-point stencil is one gather group with shifts -1, 0, +1") {
  const Kernel k = lower_one(kUpwind);
  const AdjointPlan plan = schedule_of(k);
  CHECK(plan.scatters.empty());
  CHECK(plan.remarks.empty());
  REQUIRE(plan.gathers.size() == 1);
  const GatherGroup& g = plan.gathers.front();
  CHECK(g.array == "d");
  const std::string v = k.nests[0].loops[0].var;
  // Cell c was read by iteration c - shift: d[i+1] at shift 1, d[i-1] at shift -1.
  const std::vector<std::string> got = shifts(g, v);
  CHECK(std::count(got.begin(), got.end(), v + ":-1") >= 1);
  CHECK(std::count(got.begin(), got.end(), v + ":1") >= 1);
  CHECK(std::count(got.begin(), got.end(), v + ":0") >= 1);
  for (const auto& b : g.blocks)
    for (const auto& t : b.terms)
      CHECK(t.partial != nullptr);
}

TEST_CASE("schedule: a read at a data-dependent index gets a serial scatter unit and a remark") {
  const Kernel k = lower_one(R"(
DPGEN_KERNEL void sample(DPGEN_IN const double* q, DPGEN_IN const double* x, DPGEN_OUT double* o, int n) {
  for (int i = 0; i < n; ++i) {
    int j = (int)x[i];
    j = j < 0 ? 0 : (j > n - 1 ? n - 1 : j);
    o[i] = 2.0 * q[j];
  }
})");
  const AdjointPlan plan = schedule_of(k);
  REQUIRE(plan.scatters.size() == 1);
  CHECK(plan.scatters[0].array == "q");
  REQUIRE(plan.remarks.size() == 1);
  CHECK(plan.remarks[0].text.find("scatter") != std::string::npos);
}

TEST_CASE("emit: the adjoint's signature and body follow the signature rule") {
  const Kernel k = lower_one(kUpwind);
  CHECK(adjoint_signature(k) ==
        "void up_adjoint(const double* d, double* d_adj, const double* out_adj, int n, double c)");
  const AdjointPlan plan = schedule_of(k);
  LoopPlan loops = plan_loops(plan);
  hoist_invariants(loops);
  const EmittedFile f = emit_file({loops}, "unit.cpp", "unit");
  CHECK(f.header.find(adjoint_signature(k)) != std::string::npos);
  CHECK(f.source.find("d_adj[") != std::string::npos);
  CHECK(f.source.find("out_adj[") != std::string::npos);
  CHECK(f.kernels.find("void up(") != std::string::npos);
  // Printing is a pure function of the plan: it rewrites nothing, so the same
  // plan prints the same again, and a plan made again prints the same.
  CHECK(emit_file({loops}, "unit.cpp", "unit").source == f.source);
  const AdjointPlan again = schedule_of(k);
  LoopPlan loops_again = plan_loops(again);
  hoist_invariants(loops_again);
  CHECK(emit_file({loops_again}, "unit.cpp", "unit").source == f.source);
}

// The loop-level locals an expression uses, by id (emit_util.hpp's collect).
std::map<int, LocalP> locals_of(const ExprP& e) {
  std::map<int, LocalP> locals;
  std::set<std::string> vars;
  collect(e, locals, vars);
  return locals;
}

TEST_CASE("share: a quotient read at three shifts is computed once per cell of a strip") {
  const Kernel k = lower_one(R"(
#include <dpgen/annotate.hpp>
DPGEN_KERNEL void sw(DPGEN_IN const double* q, DPGEN_IN const double* u, DPGEN_OUT double* out,
                     int n, double dx) {
  for (int i = 1; i < n - 1; ++i) {
    const double c = u[i] / dx;
    out[i] = (c > 0.0 ? c : 0.0) * (q[i] - q[i - 1]) + (c < 0.0 ? c : 0.0) * (q[i + 1] - q[i]);
  }
}
)");
  const AdjointPlan plan = schedule_of(k);
  LoopPlan loops = plan_loops(plan);
  hoist_invariants(loops);
  const CellLoop& fused = loops.inputs.at(0).gathers.at(0).loops.at(0);
  REQUIRE(fused.groups.size() == 2);
  CHECK(fused.shared.empty());
  const std::string before = emit_file({loops}, "unit.cpp", "unit").source;
  CHECK(before.find("shared0") == std::string::npos);
  share_shifted_values(loops);
  // q's terms read c at i = c_i - 1, c_i, c_i + 1 (u's at c_i only): one buffer.
  REQUIRE(fused.shared.size() == 1);
  CHECK(fused.shared[0].name == "shared0");
  CHECK(print(fused.shared[0].value) == "u[i] / dx");
  CHECK(fused.shared[0].lo == -1);
  CHECK(fused.shared[0].hi == 1);
  CHECK(fused.shared[0].outer.empty());
  // Each of q's interior terms reads it where it computed it, in its local c (defined before
  // the term, so unconditionally, though the partial uses c in a select's arm), and no local
  // of those terms divides any more.
  size_t reads = 0;
  for (const auto& per_block : fused.interior_terms.at(0))
    for (const auto& t : per_block)
      for (const auto& [id, l] : locals_of(t.partial)) {
        CHECK(print(l->def).find(" / ") == std::string::npos);
        reads += print(l->def) == "shared0[i - shared0_lo]";
      }
  CHECK(reads == 3);
  // Only the adjoint's interior: the edge terms compute it as before.
  const BoxTerm& edge = fused.edge_terms.at(0).at(0).at(0);
  bool edge_divides = false;
  for (const auto& [id, l] : locals_of(edge.partial))
    edge_divides = edge_divides || print(l->def) == "u[i] / dx";
  CHECK(edge_divides);
  const std::string after = emit_file({loops}, "unit.cpp", "unit").source;
  CHECK(after.find("double shared0[258];") != std::string::npos);
  CHECK(after.find("c_i += 256") != std::string::npos);
  // Once per plan.
  CHECK_THROWS_AS(share_shifted_values(loops), std::logic_error);
}

TEST_CASE("hoist: the pass rewrites the planned terms; emit prints them as they are") {
  // A kernel whose adjoint divides under a condition: c * u[i] / dx.
  const Kernel k = lower_one(R"(
#include <dpgen/annotate.hpp>
DPGEN_KERNEL void sc(DPGEN_IN const double* u, DPGEN_OUT double* out, int n, double dx) {
  for (int i = 0; i < n; ++i)
    out[i] = u[i] > 0.0 ? u[i] / dx : 0.0;
}
)");
  const AdjointPlan plan = schedule_of(k);
  LoopPlan loops = plan_loops(plan);
  // Before the pass: the interior term divides by dx; nothing hoisted.
  const BoxTerm& t = loops.inputs.at(0).gathers.at(0).loops.at(0).interior_terms.at(0).at(0).at(0);
  CHECK(print(t.partial).find("1.0 / dx") != std::string::npos);
  CHECK(loops.hoisted.empty());
  const std::string unhoisted = emit_file({loops}, "unit.cpp", "unit").source;
  hoist_invariants(loops);
  REQUIRE(loops.hoisted.size() == 1);
  CHECK(loops.hoisted[0]->name == "inv_dx");
  CHECK(print(loops.hoisted[0]->def) == "1.0 / dx");
  CHECK(print(t.partial).find("inv_dx") != std::string::npos);
  CHECK(print(t.partial).find("1.0 / dx") == std::string::npos);
  CHECK(t.same_everywhere == false);
  CHECK(t.factor == -1); // (it reads u: not the same in every iteration)
  // The forward form's own: u[i] / dx stays (it reads u), nothing to hoist.
  CHECK(loops.forward.hoisted.empty());
  // Once only: a second run would hoist from its own locals.
  CHECK_THROWS_AS(hoist_invariants(loops), std::logic_error);
  const std::string hoisted = emit_file({loops}, "unit.cpp", "unit").source;
  CHECK(hoisted != unhoisted);
  CHECK(hoisted.find("const auto inv_dx = 1.0 / dx;") != std::string::npos);
}

TEST_CASE("hoist: loop-invariant subexpressions, exactly as written, before the loops") {
  Kernel k;
  k.names = {"dx", "dt", "n", "u", "inv_dx", "i"};
  const ExprP dx = param("dx", Type::Double), dt = param("dt", Type::Double);
  const ExprP n = param("n", Type::Int), i = loop_var("i");
  const ExprP u = read("u", i, Type::Double, {});
  const ExprP one = real_const(1, Type::Double, "1.0"), zero0 = real_const(0, Type::Double, "0.0");
  Hoister hoist(k);
  // The partial of the upwind switch: the division under the condition goes,
  // the one that reads u stays; the name avoids the kernel's `inv_dx`.
  const ExprP upwind =
      select(binary(Op::Le, binary(Op::Div, u, dx), zero0), binary(Op::Div, one, dx), zero0);
  CHECK(print(hoist(upwind)) == "u[i] / dx <= 0.0 ? inv_dx_ : 0.0");
  // The same expression again: the same local.
  CHECK(print(hoist(binary(Op::Mul, binary(Op::Div, one, dx), u))) == "inv_dx_ * u[i]");
  // A product that a sum uses stays next to it (a fused multiply-add may
  // take both), its operands may go; a negation stays, its operand goes.
  CHECK(print(hoist(binary(Op::Add, binary(Op::Mul, dt, dx), u))) == "dt * dx + u[i]");
  CHECK(print(hoist(binary(Op::Mul, binary(Op::Mul, dt, dx), u))) == "hoisted1 * u[i]");
  CHECK(print(hoist(binary(Op::Mul, unary(Op::Neg, binary(Op::Div, dt, dx)), u))) ==
        "-(hoisted2 * u[i])");
  // Only summed where the caller says so (`x += e`).
  CHECK(print(hoist(binary(Op::Mul, dt, dx), true)) == "dt * dx");
  // An integer division may trap where the source would not run it: stays.
  const ExprP by_n = binary(Op::Div, one, cast(binary(Op::Div, int_const(100), n), Type::Double));
  CHECK(print(hoist(binary(Op::Mul, by_n, u))) == "1.0 / static_cast<double>(100 / n) * u[i]");
  Code code;
  emit_hoisted(code, hoist.hoisted());
  CHECK(code.str() == "// loop-invariant, hoisted: computed once here, the same expressions as in "
                      "the loops below\n"
                      "const auto inv_dx_ = 1.0 / dx;\n"
                      "const auto hoisted1 = dt * dx;\n"
                      "const auto hoisted2 = dt / dx;\n");
}

TEST_CASE("plan: the cell loop of a three-point stencil, its interior and the parallel test") {
  const Kernel k = lower_one(kUpwind);
  const AdjointPlan plan = schedule_of(k);
  const LoopPlan loops = plan_loops(plan);
  REQUIRE(loops.inputs.size() == 1);
  CHECK(loops.inputs[0].array == "d");
  CHECK(loops.inputs[0].scatters.empty());
  REQUIRE(loops.inputs[0].gathers.size() == 1);
  const GatherStep& step = loops.inputs[0].gathers[0];
  CHECK_FALSE(step.fused());
  const CellLoop& cl = step.loops.at(0);
  CHECK(cl.any_bulk);
  CHECK(cl.unit_1d); // d[i + s]: unit stride in one counter, no mixed-radix test
  // Iterations 1 .. n-2 read cells 0 .. n-1; every term is present (branch
  // free) for cells 2 .. n-3, i.e. the interior [2, n - 2).
  REQUIRE(cl.interior.dims.size() == 1);
  CHECK(cl.interior.dims.begin()->first == "i"); // Box::dims: counters by plain name
  const Interval& in = cl.interior.dims.begin()->second;
  std::vector<std::string> lo, hi;
  for (const auto& p : in.lo)
    lo.push_back(p.str());
  for (const auto& p : in.hi)
    hi.push_back(p.str());
  CHECK(std::find(lo.begin(), lo.end(), "2") != lo.end());
  CHECK(std::find(hi.begin(), hi.end(), "n - 2") != hi.end());
}

TEST_CASE("plan: inputs read through the same layout fuse into one loop; a 2D layout gets the "
          "mixed-radix test") {
  const Kernel k = lower_one(R"(
DPGEN_KERNEL void lap(DPGEN_IN const double* a, DPGEN_IN const double* b, DPGEN_OUT double* o,
                      int nx, int ny) {
  for (int j = 1; j < ny - 1; ++j)
    for (int i = 1; i < nx - 1; ++i)
      o[j * nx + i] = a[j * nx + i + 1] * b[j * nx + i + 1] - a[(j - 1) * nx + i - 1] * b[(j - 1) * nx + i - 1];
})");
  const AdjointPlan plan = schedule_of(k);
  const LoopPlan loops = plan_loops(plan);
  REQUIRE(loops.inputs.size() == 2);
  REQUIRE(loops.inputs[0].gathers.size() == 1);
  const GatherStep& step = loops.inputs[0].gathers[0];
  CHECK(step.fused());                     // a and b share layout j * nx + i and the cell box
  CHECK(step.loops.size() == 3);           // the fused loop, then each input alone
  CHECK(step.loops[0].groups.size() == 2); // both inputs in the fused loop
  CHECK(loops.inputs[1].gathers.empty());  // b is done inside a's step
  CHECK_FALSE(step.loops[0].unit_1d);
  CHECK(step.loops[0].radix.size() == 2); // counters by coefficient: i (1), then j (nx)
}

TEST_CASE("affine: a counter and a size are different symbols; counters order first") {
  const Poly i = Poly::counter("i"), j = Poly::counter("j");
  const Poly n = Poly::symbol("n"), big = Poly::symbol("N"), x = Poly::symbol("_x");
  CHECK_FALSE(Poly::counter("n") == n);
  CHECK((Poly::counter("n") - n).degree() == 1);
  const Poly p = j * n + i + big + x - Poly::constant(1);
  CHECK(p.mentions_counter("i"));
  CHECK_FALSE(p.mentions_counter("n"));
  CHECK(p.mentions(Sym::size("n")));
  CHECK(p.mentions_any_counter());
  CHECK_FALSE((big + x).mentions_any_counter());
  CHECK(p.coefficient(Sym::counter("j")) == n);
  CHECK(p.coefficient(Sym::size("n")) == j);
  CHECK(p.without(Sym::counter("j")) == i + big + x - Poly::constant(1));
  // Terms print counters before sizes (upper case and '_' included), the
  // constant last.
  CHECK(p.str() == "j * n + i + N + _x - 1");
  // Only a size named c_... is a cell coordinate (std::ptrdiff_t) in code().
  CHECK((n * Poly::symbol("c_j") + i).code() == "c_j * n + i");
  CHECK((n * Poly::counter("c_j")).code() == "static_cast<std::ptrdiff_t>(c_j) * n");
  CHECK(Poly::term(3, {Sym::size("n"), Sym::counter("i")}) == Poly::constant(3) * i * n);
}

// What check hands to the output as IR values (ir.hpp): size conditions,
// checks and extents, printed by code() with the live RenameScope's names.
TEST_CASE("ir: size checks and extents are polynomials, printed with the output's names") {
  const Poly n = Poly::symbol("n"), nx = Poly::symbol("nx"), one = Poly::constant(1);
  SizeCheck c;
  c.premises =
      sorted_conds({SizeCond::runs(one, n), SizeCond::nonneg(n - one), SizeCond::runs(one, n)});
  REQUIRE(c.premises.size() == 2); // in the order of their code, the repeat dropped
  CHECK(c.premises[0].code() == "(1) < (n)");
  CHECK(c.premises[1].code() == "(n - 1) >= 0");
  c.must_hold = {{SizeCond::nonneg(nx - n), SizeCond::nonneg(n - nx - one)}};
  CHECK(c.must_hold_code() == "(-n + nx) >= 0 || (n - nx - 1) >= 0");
  c.must_hold.insert(c.must_hold.begin(), {SizeCond::nonneg(nx - Poly::constant(2))});
  CHECK(c.must_hold_code() == "(nx - 2) >= 0 && ((-n + nx) >= 0 || (n - nx - 1) >= 0)");
  SizeCheck d = c;
  CHECK(d.same_as(c));
  d.premises.pop_back();
  CHECK_FALSE(d.same_as(c));

  Extent e;
  e.add({{}, n + one});
  e.add({{}, n + one}); // counted once
  CHECK(e.code() == "std::max<std::ptrdiff_t>(0, static_cast<std::ptrdiff_t>(n + 1))");
  e.add({{SizeCond::runs(Poly::constant(0), nx)}, nx * n});
  CHECK(e.code() == "std::max<std::ptrdiff_t>({0, static_cast<std::ptrdiff_t>(n + 1), "
                    "static_cast<std::ptrdiff_t>((0) < (nx) ? "
                    "static_cast<std::ptrdiff_t>(n) * nx : 0)})");
  {
    RenameScope seeds(std::map<std::string, std::string>{{"nx", "nx_adj"}});
    CHECK(c.premises[1].code() == "(n - 1) >= 0");
    CHECK(c.must_hold_code() ==
          "(nx_adj - 2) >= 0 && ((-n + nx_adj) >= 0 || (n - nx_adj - 1) >= 0)");
  }
  Extent rows;
  rows.row_length = nx;
  rows.rows = {n - one};
  CHECK(rows.code() == "std::max<std::ptrdiff_t>(0, static_cast<std::ptrdiff_t>(nx) * "
                       "std::max<std::ptrdiff_t>(0, n - 1))");
}

// The operation table (ops.hpp): its rows follow the enum, and every math
// function has a rule for each argument (a missing one would silently drop
// a derivative).
TEST_CASE("ops table: rows in enum order, a rule per argument, aliases") {
  const auto& ops = op_table();
  for (size_t i = 0; i < ops.size(); ++i) {
    CAPTURE(ops[i].name);
    CHECK(static_cast<size_t>(ops[i].op) == i);
    CHECK(&op_info(ops[i].op) == &ops[i]);
    if (ops[i].comparison) {
      CHECK(op_info(ops[i].mirror).mirror == ops[i].op);
      CHECK(op_info(ops[i].negated).negated == ops[i].op);
    }
  }
  CHECK(op_info(Op::Lt).negated == Op::Ge);
  CHECK(op_info(Op::Le).mirror == Op::Ge);
  // The lowering maps the source's binary operators through the symbol
  // column: each binary row is found by its symbol, `-` is the subtraction
  // (not the negation), and an operator the IR lacks has none.
  for (const auto& row : ops)
    if (row.arity == 2 && *row.symbol) {
      CAPTURE(row.name);
      CHECK(binary_op(row.symbol) == &row);
    }
  CHECK(binary_op("-")->op == Op::Sub);
  CHECK(binary_op("<<")->op == Op::Shl);
  CHECK(binary_op("<=>") == nullptr);
  CHECK(binary_op(",") == nullptr);
  CHECK(binary_op("!") == nullptr);
  for (const auto& f : math_functions()) {
    CAPTURE(f.name);
    bool rule = f.piecewise_constant || f.whole;
    CHECK((rule || f.partials.size() == f.arity));
    CHECK(&math_function(f.name) == &f);
    if (f.printed.empty()) { // dpgen's own (dpgen_nograd): no kernel calls it
      CHECK(find_math_function(f.name) == nullptr);
      continue;
    }
    CHECK(find_math_function(f.name) == &f);
    CHECK(find_math_function(f.name + "f") == &f); // float variant
  }
  CHECK(find_math_function("fmin")->name == "fmin"); // (printed as itself: NaN arguments)
  CHECK(find_math_function("fminf")->name == "fmin");
  CHECK(find_math_function("fabsf")->name == "abs");
  CHECK(find_math_function("tgamma") == nullptr);
  CHECK_THROWS_AS(math_function("tgamma"), std::logic_error);
}

// A tiny interpreter of real-valued IR expressions (reads by array name,
// every read at the same cell): enough to evaluate a derivative at a point.
static double evaluate(const ExprP& e, const std::map<std::string, double>& at) {
  auto arg = [&](size_t i) { return evaluate(e->ops[i], at); };
  switch (e->op) {
  case Op::IntConst:
    return double(e->ival);
  case Op::RealConst:
    return e->rval;
  case Op::Read:
    return at.at(e->name);
  case Op::Local:
    return evaluate(e->local->def, at);
  case Op::Neg:
    return -arg(0);
  case Op::Add:
    return arg(0) + arg(1);
  case Op::Sub:
    return arg(0) - arg(1);
  case Op::Mul:
    return arg(0) * arg(1);
  case Op::Div:
    return arg(0) / arg(1);
  case Op::Lt:
    return arg(0) < arg(1);
  case Op::Le:
    return arg(0) <= arg(1);
  case Op::Gt:
    return arg(0) > arg(1);
  case Op::Ge:
    return arg(0) >= arg(1);
  case Op::Select:
    return arg(0) != 0 ? arg(1) : arg(2);
  case Op::Cast:
    return arg(0);
  case Op::Call: {
    static const std::map<std::string, std::function<double(const std::vector<double>&)>> fns = {
        {"exp", [](const std::vector<double>& v) { return std::exp(v[0]); }},
        {"cos", [](const std::vector<double>& v) { return std::cos(v[0]); }},
        {"sin", [](const std::vector<double>& v) { return std::sin(v[0]); }},
        {"log", [](const std::vector<double>& v) { return std::log(v[0]); }},
        {"atan2", [](const std::vector<double>& v) { return std::atan2(v[0], v[1]); }},
        {"hypot", [](const std::vector<double>& v) { return std::hypot(v[0], v[1]); }},
        {"erf", [](const std::vector<double>& v) { return std::erf(v[0]); }},
        {"cbrt", [](const std::vector<double>& v) { return std::cbrt(v[0]); }},
        {"copysign", [](const std::vector<double>& v) { return std::copysign(v[0], v[1]); }},
        {"fma", [](const std::vector<double>& v) { return std::fma(v[0], v[1], v[2]); }},
        {"log1p", [](const std::vector<double>& v) { return std::log1p(v[0]); }},
        {"expm1", [](const std::vector<double>& v) { return std::expm1(v[0]); }},
    };
    std::vector<double> v;
    for (size_t i = 0; i < e->ops.size(); ++i)
      v.push_back(arg(i));
    return fns.at(e->name)(v);
  }
  default:
    throw std::logic_error(std::string("evaluate: no value for ") + op_info(e->op).name);
  }
}

// Each added function's rule, by value: the derivative that derive() builds
// for f(x) (f(x, y)) at a point, against a central difference.
TEST_CASE("ops table: the added functions' rules against finite differences") {
  struct Case {
    const char* code;
    double (*f)(double, double);
  };
  const Case cases[] = {
      {"std::atan2(a[i], b[i])", [](double x, double y) { return std::atan2(x, y); }},
      {"std::hypot(a[i], b[i])", [](double x, double y) { return std::hypot(x, y); }},
      {"std::erf(a[i]) + b[i]", [](double x, double y) { return std::erf(x) + y; }},
      {"std::cbrt(a[i] * b[i])", [](double x, double y) { return std::cbrt(x * y); }},
      {"std::copysign(a[i], b[i] - 2.0)", [](double x, double y) { return std::copysign(x, y - 2.0); }},
      {"std::fma(a[i], b[i], a[i] * b[i])", [](double x, double y) { return std::fma(x, y, x * y); }},
      {"std::log1p(a[i] * b[i])", [](double x, double y) { return std::log1p(x * y); }},
      {"std::expm1(a[i] - b[i])", [](double x, double y) { return std::expm1(x - y); }},
  };
  for (const auto& c : cases) {
    CAPTURE(std::string(c.code));
    std::vector<Kernel> ks;
    REQUIRE(lower(annotate_header() + "\n#include <cmath>\nDPGEN_KERNEL void k(DPGEN_IN const "
                  "double* a, DPGEN_IN const double* b, DPGEN_OUT double* out, int n) {\n"
                  "  for (int i = 0; i < n; ++i) out[i] = " + std::string(c.code) + ";\n}\n",
                  ks));
    // Evaluates the partial of the store w.r.t. each read at a = 0.7, b = 1.3
    // by printing it into a tiny interpreter: the IR's own evaluator.
    // (an array read twice, as a[i] * b[i] next to fma(a[i], ...), gets the
    // sum of its reads' partials).
    const Store& st = ks[0].nests[0].stores[0];
    const double x = 0.7, y = 1.3, h = 1e-6;
    std::map<std::string, double> total;
    for (const auto& site : reads_in(st.value)) {
      DeriveNames names;
      ExprP d = derivative(st.value, {site.read}, names);
      CAPTURE(print(d));
      total[site.read->name] += evaluate(d, {{"a", x}, {"b", y}});
    }
    CHECK(total["a"] == doctest::Approx((c.f(x + h, y) - c.f(x - h, y)) / (2 * h)).epsilon(1e-6));
    CHECK(total["b"] == doctest::Approx((c.f(x, y + h) - c.f(x, y - h)) / (2 * h)).epsilon(1e-6));
  }
}
