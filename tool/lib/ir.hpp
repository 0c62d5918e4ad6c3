// The kernel IR: what the lowering phase makes of a DPGEN_KERNEL function and
// what every later phase (derive, schedule, emit) works on. Expressions are
// immutable DAG nodes; a kernel is a list of loop nests, each a list of stores
// with the path condition under which they execute.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "poly.hpp"

namespace dpgen {

/// A position in the user's source, for diagnostics.
struct SourcePos {
  std::string file;
  unsigned line = 0;
  unsigned col = 0;
  /// The front end's own handle on the position (a Clang SourceLocation's
  /// raw encoding; 0: none), so that a diagnostic at it shows the macro
  /// expansions behind it as Clang would. Later phases ignore it.
  std::uint64_t loc = 0;
};

enum class Type { Int, Float, Double, Bool };

inline bool is_real(Type t) { return t == Type::Float || t == Type::Double; }

enum class Op {
  IntConst,  // ival
  RealConst, // rval, spelling
  Param,     // scalar parameter `name`
  LoopVar,   // loop induction variable `name`
  Local,     // a named local value: `local`
  Read,      // name[ops[0]]
  Neg,
  Add,
  Sub,
  Mul,
  Div,
  Rem,
  Lt,
  Le,
  Gt,
  Ge,
  Eq,
  Ne,
  And,
  Or,
  Not,
  Select, // ops[0] ? ops[1] : ops[2]
  Call,   // name(ops...), name is one of the supported math functions
  Cast,   // conversion of ops[0] to `type`
  // Integer bit operations (index and branch logic: i << 1, (i + j) & 1).
  Shl,
  Shr,
  BitAnd,
  BitOr,
  BitXor,
  BitNot,
};

struct Expr;
using ExprP = std::shared_ptr<const Expr>;

/// How an array's flat IR index is written back as C++: `levels` pointer
/// levels (pointer_levels(Param)) and, for an array view (Param::view), the
/// view's call operator instead of subscripts: `a(k, j, i)` for a[k][j][i].
struct Shape {
  int levels = 0;
  bool view = false;
};

/// One condition on a store's path: `cond` held (positive) or did not.
struct PathCond {
  ExprP cond;
  bool positive;
};

/// A local variable of the kernel after SSA renaming: every assignment makes a
/// new Local, so a Local has exactly one definition.
struct LocalVar {
  std::string name;      // unique within the kernel
  std::string type_name; // as spelled in the emitted code ("double", "int")
  ExprP def;
  int id = 0;                // creation order; definitions only use lower ids
  bool kernel_level = false; // defined outside every loop (depends on params only)
  /// A symbol in index algebra whatever its definition (a row-pointer
  /// array's row length, ir.hpp: row_symbol).
  bool opaque = false;
  /// The path conditions open where it was made (lower.cpp's path_): a value
  /// made in an arm has more than a store it is merged into past the arm
  /// (lower_guard.cpp: Guards::guarded).
  std::vector<PathCond> made_under;
};
using LocalP = std::shared_ptr<const LocalVar>;

struct Expr {
  Op op;
  Type type;
  std::vector<ExprP> ops;
  long long ival = 0;
  double rval = 0;
  std::string name; // Param, LoopVar, Read (array), Call (function)
  std::string spelling;  // RealConst: the literal as written in the kernel ("0.5", "1e-3")
  std::string source;    // Read: the read as written ("u[i - 1]"), for comments and remarks
  std::string cast_type; // Cast: the integer type of a widening cast as spelled ("long")
  LocalP local;     // Local
  /// Read: the pointer levels of the array (pointer_levels(Param)): 1 for
  /// a[j][i] of `double** a`, 2 for a[k][j][i] of `double*** a`, else 0; and
  /// whether it is an array view, read as a(k, j, i). The printer needs it
  /// where the flat index has no row symbol (row 0).
  Shape shape;
  SourcePos pos;    // Read: where it is in the source (for remarks)
  /// RealConst: the exact zero of derivative code (zero()), as opposed to a
  /// 0.0 the kernel wrote. Derivative rules fold it (0·x = 0, 0 + x = x).
  bool exact_zero = false;
};

// Constructors. They fold the trivial cases (x*1, x+0, -(-x), constants) so
// derivatives come out readable. No ExprP in the IR or a plan is null: an
// exact zero in derivative code is zero() (see derive.hpp).
ExprP int_const(long long v);
ExprP real_const(double v, Type t, std::string spelling = "");
ExprP param(const std::string& name, Type t);
ExprP loop_var(const std::string& name);
ExprP local_ref(const LocalP& l);
ExprP read(const std::string& array, ExprP index, Type t, SourcePos pos, Shape shape = {});
ExprP unary(Op op, ExprP a);
ExprP binary(Op op, ExprP a, ExprP b);
ExprP select(ExprP c, ExprP a, ExprP b);
/// The conjunction of path[from..to) (each condition, or its negation, and-ed
/// left to right) as one condition; null where the range is empty.
ExprP path_condition(const std::vector<PathCond>& path, size_t from = 0, size_t to = SIZE_MAX);
ExprP call(const std::string& fn, std::vector<ExprP> args, Type t);
/// The value of an integer expression of constants only (after unrolling,
/// `m % 2` with m = 3), with C's semantics (division truncates); nullopt if
/// it depends on anything else, divides by zero or overflows a shift.
std::optional<long long> int_value(const ExprP& e);
ExprP cast(ExprP a, Type t);

/// The exact zero of derivative code: a RealConst 0 of type `t`, marked
/// exact_zero. It prints as 0.0 (a conditional's arm that carries no
/// derivative); derive.cpp folds it out of sums and products, and consumers
/// test is_zero() where a derivative may vanish.
ExprP zero(Type t);
/// Whether `e` is zero() (not a 0.0 the kernel wrote). A null `e` is an
/// internal error (std::logic_error).
bool is_zero(const ExprP& e);

/// `e` with every operand replaced by f(operand); `e` itself if none changed.
template <typename F> ExprP map_operands(const ExprP& e, F&& f) {
  bool changed = false;
  std::vector<ExprP> ops;
  for (const auto& o : e->ops) {
    ops.push_back(f(o));
    changed = changed || ops.back() != o;
  }
  if (!changed)
    return e;
  auto copy = std::make_shared<Expr>(*e);
  copy->ops = std::move(ops);
  return copy;
}

/// A switch over Op with a case for every value was given a value outside
/// the enum: an internal error (std::logic_error) naming `where`.
[[noreturn]] void unknown_op(const char* where);

/// The message of an internal error (an exception from a broken invariant)
/// caught while pass `pass` ran on kernel `kernel`: says that it is a bug in
/// dpgen, not in the user's kernel. Reported with the id dpgen-internal.
std::string internal_error_message(const std::string& kernel, const std::string& pass,
                                   const std::string& what);
/// For the tests of that report: throws std::logic_error when the environment
/// variable DPGEN_TEST_INTERNAL_ERROR names `pass`.
void test_internal_error(const char* pass);

bool is_const(const ExprP& e, double v);
/// Structural equality (Locals compare by identity).
bool same(const ExprP& a, const ExprP& b);

enum class ParamKind { In, Out, ConstArray, Scalar };

struct Param {
  std::string name;
  ParamKind kind;
  Type elem;             // element type of an array, type of a scalar
  std::string elem_name; // "double", "float", "int", ...
  std::string spelling;  // the parameter's declaration as written in the source
  /// Row extents of a pointer to rows (`double (*a)[64]`, `double a[][64]`):
  /// "[64]". Such an array is indexed a[j][i], read as the flat a[j * 64 + i];
  /// the generated adjoint takes it in the same shape.
  std::string rows;
  /// The declaration as C++ with canonical types, e.g. `const double* a`.
  std::string declaration;
  /// A std::vector<T>& parameter: its type ("std::vector<double>"). The
  /// kernel's size() of it is the synthetic parameter `<name>_size` after it.
  std::string container;
  /// The container is a std::span<T> taken by value (`container` names it
  /// without the constness, which goes on the element: std::span<const T>).
  bool span = false;
  /// Not in the user's signature: the size dpgen passes for a vector.
  bool synthetic = false;
  /// DPGEN_INOUT: an array updated in place, element by element. In the IR
  /// it is an input (its values before the call, `inout` set) and an output
  /// twin `<name>_new` (`twin_of` names the input) that receives the stores.
  bool inout = false;
  std::string twin_of;
  /// Rows reached through pointers (`double** a`, a[j][i]). Assumed: every
  /// row is an array of its own (rows do not overlap one another, nor any
  /// other array's rows), holding the columns the kernel touches. In the IR
  /// a[j][i] is the flat element j * R + i with the symbol R =
  /// row_symbol(a) standing for a row length larger than any column index;
  /// the printer turns such indices back into [j][i].
  bool row_pointers = false;
  /// `double*** a` (a[k][j][i]): planes of rows. k * P + j * R + i, with
  /// P = plane_symbol(a) larger than any j * R + i.
  bool plane_pointers = false;
  /// `std::vector<std::vector<double>>& a` (a[j][i]): rows through pointers
  /// in the IR (row_pointers); the entry points take the vectors (their
  /// rows' sizes checked against each other) and pass the flat twin each
  /// row's data() (dpgen/row_pointers.hpp).
  bool nested = false;
  /// An enum scalar (`Bc bc`): generated code reads it through an integer
  /// copy, `<name>_value` (a scoped enum does not compare with integers).
  bool enum_value = false;
  /// An unsigned integer scalar (`unsigned n`, `size_t n`): generated code
  /// reads it through a signed copy, `<name>_signed`.
  bool is_unsigned = false;
  /// A scalar passed by reference and annotated (`DPGEN_OUT double& mass`,
  /// `DPGEN_IN const double& c`): in the IR a one-element array (`mass` is
  /// mass[0]). The adjoint's user-facing entry point takes an output's seed by
  /// value (`double mass_adj`) and an input's adjoint by reference
  /// (`double& c_adj`), and passes their addresses to the flat one.
  bool scalar_ref = false;
  /// The kernel's return value (`double checksum(...)`): an output
  /// `<kernel>_return` (scalar_ref) after every declared parameter, in no
  /// forward signature. Its seed is the adjoint's trailing
  /// `<kernel>_return_adj`; the tangent returns the value and takes
  /// `<kernel>_return_dot` by reference.
  bool returned = false;
  /// An unnamed parameter of an empty class type (`XDir`, a
  /// std::integral_constant): a tag that picks an overload. A Scalar named
  /// `dpgen_tag_<position>` in every generated signature, passed along.
  bool tag = false;
  /// A tag's declaration for generated headers, which do not include the
  /// kernel file: "namespace d { struct XDir; }" or "#include <type_traits>".
  std::string tag_declaration;
  /// A global the kernel reads (`double g_dx;`, `DPGEN_IN double* g_kappa;`,
  /// `DPGEN_IN double g_diff[3];`, a constexpr table): in no signature; the
  /// generated files declare it (`global_declaration`: "extern double*
  /// g_kappa;", or a static copy of a constant table's values) in its
  /// namespaces (`global_namespaces`) and name it unqualified. A DPGEN_IN
  /// global's adjoint (tangent) is the global pointer `<name>_adj`
  /// (`<name>_dot`), defined by the generated .cpp, declared by its header;
  /// the caller points it at storage (null: not differentiated).
  bool global = false;
  /// A global array's number of elements where its type gives it (`double table[4]`); -1
  /// else (a pointer). The checked entry point checks what the kernel reads of it.
  long long global_count = -1;
  std::string global_declaration;
  std::vector<std::string> global_namespaces;
  /// An array view: a parameter of a class type whose inline operator() is
  /// an affine, one-to-one map of its `view_rank` indices to the elements of
  /// a pointer member (AMReX Array4, Kokkos::View, mdspan, an AthenaArray-like
  /// class). In the IR a(k, j, i) is the flat k * P + j * R + i with the row
  /// and plane symbols of row-pointer arrays (a view's layout gives distinct
  /// indices distinct elements, as rows of their own would); generated code
  /// reads and writes it through its own operator(). `view_type` is the
  /// parameter's type as the kernel declares it ("const
  /// amrex::Array4<const double>&"; `view_reference`: a reference);
  /// `view_class` the same view over non-const elements
  /// ("amrex::Array4<double>"), the class of an adjoint or tangent of it,
  /// taken as `view_pass` says (view_declared_type). The generated headers
  /// include what declares the class (`tag_declaration`: `#include
  /// "amrex_lite.hpp"`, as the kernel file spells it).
  bool view = false;
  int view_rank = 0;
  std::string view_type;
  bool view_reference = false;
  std::string view_class;
  enum class ViewPass {
    Value,    // as the kernel takes it
    ConstRef, // a shallow view (its const operator() gives non-const elements)
    Ref,      // a deep-const class (AthenaArray-like): by non-const reference
  } view_pass = ViewPass::Value;
  /// A work array's view in a stage of a staged adjoint (schedule.cpp): the
  /// driver's dpgen::ViewBuffer (view_buffer_type), taken by const reference
  /// as the array and as its adjoint.
  bool view_buffered = false;
  /// An unannotated parameter of a class type that is no view (AMReX's `Box
  /// const& bx`, a struct of grid constants): passed along unchanged, read
  /// only through its integer and floating members (constants of the kernel,
  /// never differentiated). A Scalar whose `spelling` is its type.
  bool object = false;
  /// A member of a member kernel's class (Kernel::member_class) that the
  /// method reads or writes: named as the member, before the method's own
  /// parameters; the generated wrapper takes it from `self`.
  bool member = false;
};

/// How many pointer levels lead to an element: 0 for a flat array (or rows
/// of fixed length), 1 for row pointers (`double** a`), 2 for planes of rows
/// (`double*** a`). The printer writes a flat index back as that many
/// subscripts plus one.
inline int pointer_levels(const Param& p) {
  if (p.view)
    return p.view_rank - 1; // a view of rank 3: a(k, j, i) as k * P + j * R + i
  return p.plane_pointers ? 2 : p.row_pointers ? 1 : 0;
}

inline Shape shape_of(const Param& p) { return {pointer_levels(p), p.view}; }

/// While a RenameScope lives, the texts of parameters and objects that
/// print() and Poly::code() write (and `renamed` of stored condition texts)
/// spell each identifier of `renames` (not one after `.`, `->` or `::`) by
/// its new name. The adjoint has no output view, only its seed of the same
/// shape and bounds: `un.cols()` reads `un_adj.cols()` there. Scopes nest:
/// the innermost one applies.
class RenameScope {
public:
  explicit RenameScope(std::map<std::string, std::string> renames);
  ~RenameScope();
  RenameScope(const RenameScope&) = delete;
  RenameScope& operator=(const RenameScope&) = delete;
};
/// `text` with the live RenameScope's identifiers renamed (unchanged if none).
std::string renamed(const std::string& text);
/// Whether `text` (generated C++) has `name` as a whole identifier.
bool names_identifier(const std::string& text, const std::string& name);

/// The generated adjoint's storage for a view output it recomputes or whose
/// adjoint it accumulates (a work array): a dpgen::ViewBuffer laid out like
/// the output's seed, "dpgen::ViewBuffer<amrex::Array4<double>, double>"
/// (runtime/include/dpgen/view_buffer.hpp).
std::string view_buffer_type(const Param& p);
/// The type generated code declares view `p` with: the kernel's own
/// (`view_type`) for the array an adjoint reads (`is_const`); its
/// `view_class` taken as `view_pass` says for an adjoint or tangent of it; a
/// stage's buffer (`view_buffered`) by const reference either way.
std::string view_declared_type(const Param& p, bool is_const);
/// Whether generated code takes view `p` by reference (its copy may be deep).
bool view_by_reference(const Param& p);

/// The symbol standing for the (unbounded) row length of row-pointer array `a`.
inline std::string row_symbol(const std::string& array) { return "dpgen_rows_" + array; }
inline std::string plane_symbol(const std::string& array) { return "dpgen_planes_" + array; }
/// The third level of a rank-4 view (Param::view): a(n, k, j, i) is
/// n * C + k * P + j * R + i.
inline std::string cube_symbol(const std::string& array) { return "dpgen_cubes_" + array; }
/// The rank (1 rows, 2 planes, 3 cubes) of such a symbol's name; 0 for any other.
inline int level_of_symbol(const std::string& name) {
  return name.rfind("dpgen_cubes_", 0) == 0    ? 3
         : name.rfind("dpgen_planes_", 0) == 0 ? 2
         : name.rfind("dpgen_rows_", 0) == 0   ? 1
                                               : 0;
}
/// The values they have in generated code: R larger than any column index, P
/// larger than any row index times R, small enough that no product with an
/// index overflows 64 bits. (With planes, columns stay below 2^30.)
constexpr long long kRowSymbolValue = 1LL << 40;
constexpr long long kPlaneRowSymbolValue = 1LL << 30;
constexpr long long kPlaneSymbolValue = 1LL << 61;
/// Those of a rank-4 view: every index below 2^19 in magnitude.
constexpr long long kCubeRowSymbolValue = 1LL << 20;
constexpr long long kCubePlaneSymbolValue = 1LL << 40;
constexpr long long kCubeSymbolValue = 1LL << 60;

struct Loop {
  std::string var;
  std::string type_name; // "int", "long", ...
  ExprP lo, hi;          // lo <= var < hi; both depend on parameters only
  /// The source counts down (`for (j = n - 1; j >= 0; --j)`): the same
  /// iterations, later ones at smaller counters (what "later" means when one
  /// iteration overwrites another's element, check.cpp: last_writer).
  bool descending = false;
};

struct Store {
  std::string array;
  ExprP index;
  ExprP value;
  std::vector<PathCond> path;
  SourcePos pos;
  /// `out[k] += value`: adds to what the element held (the caller's contents
  /// or an earlier store). The adjoint is the same as for `=`; the write-once
  /// rule does not apply (a reduction or a flux accumulation is fine), but a
  /// later `=` must not overwrite it.
  bool accumulate = false;
  /// A min/max scan (`m = std::max(m, e)` in a loop, lower_reduce.cpp): with
  /// `accumulate`, +1 stores max(element, value), -1 min(element, value).
  /// Its value is a constant to every derivative (dpgen_nograd): the
  /// reduction's derivative comes from the separate sums lowering builds.
  int extremum = 0;
  /// `+=` statements into one element merged into this store (`x += a; x +=
  /// b;`, value a + b): the element's new value as the kernel computes it,
  /// (x + a) + b, which the forward forms print for the same bits. Null
  /// where `x += value` is that.
  ExprP chain;
  /// Program order of the store statements in the kernel.
  int seq = 0;
};

struct Nest {
  std::vector<Loop> loops; // outermost first; may be empty for straight-line code
  std::vector<Store> stores;
  /// Which `for` statements the nest runs in: a number per loop, outermost
  /// first, then its segment (straight-line code after a loop gets a nest of
  /// its own). Two nests share their first n entries when they share n
  /// outer loops; no two nests have the same key (check.cpp).
  std::vector<int> key;
};

/// A condition over the sizes (parameters, kernel-level locals): `a >= 0`,
/// or, for a loop over [a, b) that runs, `a < b`.
struct SizeCond {
  Poly a, b;
  bool less = false;

  static SizeCond nonneg(Poly p) { return {std::move(p), Poly(), false}; }
  static SizeCond runs(Poly lo, Poly hi) { return {std::move(lo), std::move(hi), true}; }
  /// C++: "(a) >= 0", "(a) < (b)" (with the live RenameScope's names).
  std::string code() const;
};

/// The conditions in the order of their code, each once (a SizeCheck's premises).
std::vector<SizeCond> sorted_conds(std::vector<SizeCond> v);
/// The conditions' C++ (code()) joined by `sep` (" && ", " || ").
std::string join_code(const std::vector<SizeCond>& conds, const char* sep);

/// A condition on the sizes that the generated adjoint checks on entry, for a
/// write-once rule dpgen could not prove from the kernel alone (a fixed row
/// length against a size parameter, two loops whose ranges are apart only for
/// some sizes).
struct SizeCheck {
  /// Where the rule matters (the loops run, ...), in the order of their code.
  std::vector<SizeCond> premises;
  /// What must hold there: each entry holds, an entry of several conditions
  /// when one of them does.
  std::vector<std::vector<SizeCond>> must_hold;
  std::string what; // "output 'u' is written once per element"
  SourcePos pos;

  /// C++ of `must_hold`: "A && (B || C)" (one entry of alternatives: "B || C").
  std::string must_hold_code() const;
  /// The same check (its conditions' code equal).
  bool same_as(const SizeCheck& o) const;
};

/// How many elements an output's stores (and later reads) can reach: the
/// count of the buffer the adjoint allocates for it.
struct Extent {
  /// One past the largest index of one access, counted where `runs` hold
  /// (the loops around a store at an element that stays while they run).
  struct End {
    std::vector<SizeCond> runs;
    Poly end;
  };
  /// The largest of these, 0 at least (each counted once).
  std::vector<End> ends;
  /// A line buffer instead: its row length times each count of rows.
  std::optional<Poly> row_length;
  std::vector<Poly> rows;

  /// Adds one end unless the same is there.
  void add(End e);
  /// C++ (std::ptrdiff_t) for the count (with the live RenameScope's names).
  std::string code() const;
};

struct Kernel {
  std::string name;
  std::vector<std::string> namespaces;
  std::vector<Param> params;
  /// Work arrays dpgen made from the kernel's scalar accumulators (`s += f(a[i])`
  /// in a loop, `s` read after it): one element per iteration of the loops
  /// around the accumulating loop, written `= init` before it, `+=` in it,
  /// read after it. DPGEN_OUT arrays of the IR (and intermediates), but in
  /// no signature: the adjoint recomputes them (emit_forward.hpp) into
  /// buffers of its own. find_param finds them.
  std::vector<Param> hidden;
  std::vector<LocalP> kernel_locals;
  /// `if (...) return;` in the kernel outside every loop, as the condition
  /// under which the kernel goes on (also on the path of every later store).
  std::vector<PathCond> guards;
  std::vector<Nest> nests;
  std::vector<SizeCheck> size_checks;
  /// Outputs that later loop nests read (work arrays). The adjoint recomputes
  /// them with the forward kernel and runs the nests in reverse order.
  std::set<std::string> intermediates;
  /// For each output the adjoint keeps a buffer of: how many elements its
  /// stores can reach (one past the largest index).
  std::map<std::string, Extent> extent;
  /// Every name the kernel brings into generated code: its parameters, loop
  /// counters and locals (as renamed by lower), and the adjoint and tangent
  /// parameters the signature rule derives from its arrays (<name>_adj,
  /// <name>_dot). Identifiers that dpgen makes up avoid them (fresh()).
  std::set<std::string> names;
  SourcePos pos;
  std::string file;       // source file as given on the command line
  bool c_linkage = false; // a C kernel: its adjoint is declared extern "C"
  /// The forward kernel's return type as spelled ("double"); "void" unless
  /// a parameter is `returned`.
  std::string return_type = "void";
  /// One instantiation of a template kernel (`template <typename Real, int
  /// Dir> void gradient(...)`, instantiated by the file as gradient<double,
  /// 0>): `name` is then unique per instantiation ("gradient_double_0", the
  /// generated functions' names), `template_name` the user's ("gradient"),
  /// `template_head` "template <typename Real, int Dir>", `template_args`
  /// "<double, 0>", and `generic_types` each parameter's element (or scalar)
  /// type as the template spells it ("Real"). The adjoint and tangent headers
  /// declare `gradient_adjoint<Real, Dir>` with an explicit specialization per
  /// instantiation calling the generated function.
  std::string template_name, template_head, template_args;
  /// A member kernel (`DPGEN_KERNEL void step(double dt) const;` of class
  /// Heat1D): the class ("Heat1D", qualified) and the method ("step"); `name`
  /// is then "Heat1D_step_members", the generated functions over the members
  /// (Param::member) and the method's parameters, which the wrappers
  /// `Heat1D_step_adjoint(const Heat1D& self, ...)` and `..._tangent` call.
  std::string member_class, member_method;
  /// Declarations generated headers need for types the kernel's objects
  /// name (a work tag in a policy's type: "struct FaceX;").
  std::vector<std::string> declarations;
  std::map<std::string, std::string> generic_types;
  /// A scalar parameter's whole type as the template spells it ("const Real&").
  std::map<std::string, std::string> generic_scalars;

  /// A name for an identifier of generated code (an accumulator, a cell
  /// counter, a size): `base`, with '_' appended while the kernel has a name
  /// of that spelling, so that no generated identifier is ever one of the
  /// user's (or shadows it).
  std::string fresh(std::string base) const {
    while (names.count(base))
      base += '_';
    return base;
  }

  /// The kernel as the user names it: "gradient<double, 0>" for an
  /// instantiation of a template kernel, else `name`.
  std::string display_name() const {
    if (!member_class.empty())
      return member_class + "::" + member_method;
    return template_name.empty() ? name : template_name + template_args;
  }

  /// pointer_levels() of array parameter `n`; 0 if there is none of that name.
  int levels_of(const std::string& n) const {
    const Param* p = find_param(n);
    return p ? pointer_levels(*p) : 0;
  }
  /// shape_of() array parameter `n`; flat if there is none of that name.
  Shape shape_of(const std::string& n) const {
    const Param* p = find_param(n);
    return p ? dpgen::shape_of(*p) : Shape{};
  }

  const Param* find_param(const std::string& n) const {
    for (const auto& p : params)
      if (p.name == n)
        return &p;
    for (const auto& p : hidden)
      if (p.name == n)
        return &p;
    return nullptr;
  }
};

std::string type_spelling(Type t);

/// A hidden array (Kernel::hidden) that holds a line buffer of the kernel
/// (a local array of more than 64 elements or of a run-time length), one row
/// per iteration of the loops around its uses, rather than an accumulator's
/// sums.
inline bool is_buffer(const Param& p) { return p.name.rfind("dpgen_buf_", 0) == 0; }

} // namespace dpgen
