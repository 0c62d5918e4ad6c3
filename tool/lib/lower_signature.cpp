// Lowering, the signature: parameters, their annotations and shapes, and the
// names generated code will need (lower_signature.hpp).
#include "lower_impl.hpp"

#include "print.hpp"

#include <algorithm>

namespace dpgen::lowering {

// `static_cast<std::ptrdiff_t>(name)`: an enum parameter as the integer the
// IR compares with its enumerators.
static ExprP enum_as_integer(const std::string& name) {
  auto as_int = std::make_shared<dpgen::Expr>();
  as_int->op = Op::Cast;
  as_int->type = Type::Int;
  as_int->ops = {param(name, Type::Int)};
  as_int->cast_type = "std::ptrdiff_t";
  return as_int;
}

void Signature::header() {
  // A member kernel (`DPGEN_KERNEL void step(double dt) const;` of class
  // Heat1D): the members it reads are parameters before the method's own,
  // the annotated ones arrays (Kernel::member_class).
  const auto* method = dyn_cast<CXXMethodDecl>(L.fn_);
  if (method && (method->isStatic() || method->getParent()->isLambda()))
    method = nullptr; // (a static member function is a free function in a class)
  if (method) {
    const CXXRecordDecl* rd = method->getParent();
    if (rd->isDependentContext() || isa<ClassTemplateSpecializationDecl>(rd))
      L.fail(L.fn_->getLocation(), "a member kernel of a class template is outside the kernel "
                               "subset: make the kernel a member of a class",
           "dpgen-signature");
    if (isa<CXXConstructorDecl>(method) || isa<CXXDestructorDecl>(method) ||
        method->isOverloadedOperator())
      L.fail(L.fn_->getLocation(), "a member kernel is a named method (not a constructor, "
                               "destructor or operator)",
           "dpgen-signature");
    L.self_class_ = rd;
  }
  // (a template kernel is lowered per instantiation, find.cpp)
  if (L.fn_->isTemplated() || (L.fn_->getTemplatedKind() != FunctionDecl::TK_NonTemplate &&
                             L.fn_->getTemplatedKind() !=
                                 FunctionDecl::TK_FunctionTemplateSpecialization))
    L.fail(L.fn_->getLocation(), "this kind of template kernel is outside the kernel subset "
                             "(a function template at namespace scope is in it)",
         "dpgen-signature");
  QualType ret = L.fn_->getReturnType();
  std::optional<Type> returns;
  if (!ret->isVoidType()) {
    returns = L.scalar_type(ret.getUnqualifiedType());
    if (!returns || !is_real(*returns))
      L.fail(L.fn_->getLocation(), fmt::format("a DPGEN_KERNEL returns void, float or double, not "
                                           "'{}'; other results go to DPGEN_OUT arrays",
                                           ret.getAsString()),
           "dpgen-signature");
  }
  if (L.fn_->isVariadic())
    L.fail(L.fn_->getLocation(), "a DPGEN_KERNEL must not be variadic", "dpgen-signature");

  L.k_.name = L.fn_->getNameAsString();
  if (L.self_class_) {
    L.k_.member_class = L.self_class_->getQualifiedNameAsString();
    L.k_.member_method = L.k_.name;
    L.k_.name = fmt::format("{}_{}_members", L.self_class_->getNameAsString(), L.k_.member_method);
  }
  L.k_.pos = L.pos(L.fn_->getLocation());
  for (const DeclContext* dc = L.fn_->getDeclContext(); dc; dc = dc->getParent())
    if (const auto* ns = dyn_cast<NamespaceDecl>(dc))
      L.k_.namespaces.insert(L.k_.namespaces.begin(), ns->getNameAsString());

  any_in_ = any_out_ = false;
  bool params_ok = true;
  // The members first, in declaration order: those the method (and the
  // lambdas and call operators of its class it runs) reads or writes.
  if (L.self_class_) {
    std::set<const FieldDecl*> used = used_fields();
    for (const FieldDecl* f : L.self_class_->fields()) {
      if (!used.count(f) && annotation(f).empty()) // (every annotated one: the signature's)
        continue;
      try {
        size_t before = L.k_.params.size();
        parameter(f);
        for (size_t i = before; i < L.k_.params.size(); ++i)
          L.k_.params[i].member = true;
      } catch (const Rejected&) {
        L.failed_ = true;
        params_ok = false;
        L.poisoned_.insert(f);
      }
    }
  }
  for (const ParmVarDecl* p : L.fn_->parameters()) {
    try {
      parameter(p);
    } catch (const Rejected&) {
      L.failed_ = true;
      params_ok = false;
      L.poisoned_.insert(p);
    }
  }
  if (returns) { // the return value: an output after every parameter
    Param r;
    r.name = (L.self_class_ ? L.k_.member_method : L.k_.name) + "_return";
    r.kind = ParamKind::Out;
    r.elem = *returns;
    r.elem_name = Lowerer::spelled(ret.getUnqualifiedType());
    r.spelling = r.elem_name + "&";
    r.declaration = r.elem_name + "& " + r.name;
    r.scalar_ref = true;
    r.returned = true;
    for (const auto& other : L.k_.params)
      if (other.name == r.name)
        L.fail(L.fn_->getLocation(), fmt::format("parameter '{}' has the name dpgen gives the return "
                                             "value of '{}'; rename it",
                                             r.name, L.k_.name),
             "dpgen-name");
    L.k_.params.push_back(r);
    L.k_.return_type = r.elem_name;
    any_out_ = true;
  }
  Globals(L).lower(L.fn_->getBody()); // lower_globals.cpp
  for (const auto& p : L.k_.params)
    any_in_ = any_in_ || (p.global && p.kind == ParamKind::In);
  check_parameter_names();
  // (no DPGEN_IN or DPGEN_OUT may only mean that one was rejected)
  if (!any_in_ && params_ok)
    L.fail(L.fn_->getLocation(), fmt::format("kernel '{}' has no DPGEN_IN parameter: there is "
                                         "nothing to differentiate",
                                         L.k_.display_name()), "dpgen-signature");
  if (!any_out_ && params_ok)
    L.fail(L.fn_->getLocation(), fmt::format("kernel '{}' has no DPGEN_OUT parameter and returns nothing", L.k_.display_name()), "dpgen-signature");
  // Row-pointer arrays: a[j][i] is the flat j * R + i for a row length R
  // that is larger than any column (a symbol; its value in the generated
  // code, kRowSymbolValue, is only ever compared, never used as an address).
  for (const auto& p : L.k_.params)
    if (p.row_pointers) {
      L.row_lengths_[p.name] = L.opaque_symbol(
          row_symbol(p.name), p.plane_pointers ? kPlaneRowSymbolValue : kRowSymbolValue);
      if (p.plane_pointers)
        L.plane_lengths_[p.name] = L.opaque_symbol(plane_symbol(p.name), kPlaneSymbolValue);
    }
  // Unsigned integer parameters (`unsigned n`, `size_t n`, a vector's
  // size) are read through a signed 64-bit copy defined first in every
  // generated function (`const std::ptrdiff_t n_signed = n;`): index
  // arithmetic in the adjoint goes below zero (`-n + 1`, `i = c_i + n - 1`),
  // which unsigned arithmetic would wrap to huge values. Enum parameters
  // likewise, through `const std::ptrdiff_t bc_value =
  // static_cast<std::ptrdiff_t>(bc);` (case labels and comparisons with its
  // enumerators are integers in the IR).
  for (const auto& p : L.k_.params)
    if (p.kind == ParamKind::Scalar && p.elem == Type::Int && p.is_unsigned)
      L.signed_views_[p.name] = L.integer_copy(p.name, "signed", param(p.name, Type::Int));
    else if (p.kind == ParamKind::Scalar && p.enum_value)
      L.enum_views_[p.name] = L.integer_copy(p.name, "value", enum_as_integer(p.name));
  L.k_.hidden.reserve(Lowerer::kMaxAccumulators); // (start_accumulator: pointers stay valid)
  // Bind parameters (after the vector is complete, so pointers stay valid).
  // By name: a rejected parameter has no Param (and is poisoned).
  for (const auto& p : L.k_.params) {
    if (p.synthetic || !p.twin_of.empty())
      continue;
    Binding b;
    b.kind = p.kind == ParamKind::Scalar ? Binding::ScalarParam : Binding::ArrayParam;
    b.param = &p;
    if (p.global) {
      L.env_[L.global_decls_.at(p.name)] = b;
      continue;
    }
    if (p.member) {
      for (const FieldDecl* f : L.self_class_->fields())
        if (f->getNameAsString() == p.name && !L.poisoned_.count(f))
          L.fields_[f] = b;
      continue;
    }
    for (const ParmVarDecl* decl : L.fn_->parameters())
      if (decl->getNameAsString() == p.name && !L.poisoned_.count(decl))
        L.env_[decl] = b;
  }
  // Mixed precision between inputs and outputs is almost always a mistake.
  std::optional<Type> real;
  for (const auto& p : L.k_.params)
    if (p.kind == ParamKind::In || p.kind == ParamKind::Out) {
      if (real && *real != p.elem)
        L.fail(L.fn_->getLocation(), fmt::format("kernel '{}' mixes float and double arrays "
                                             "('{}' is {}); use one precision for all "
                                             "DPGEN_IN and DPGEN_OUT arrays",
                                             L.k_.name, p.name, type_spelling(p.elem)), "dpgen-signature");
      real = p.elem;
    }
}

// One parameter; an error in it is reported, the parameter poisoned (its
// uses are not reported again) and the rest of the kernel still lowered,
// so one run reports every error of the file.
void Signature::parameter(const DeclaratorDecl* p) {
  Param out;
  out.name = p->getNameAsString();
  std::string ann = annotation(p);
  if (out.name.empty()) { // a tag
    tag_parameter(p, ann, out);
    return;
  }
  QualType q = p->getType();
  std::optional<Param> size_param;
  std::optional<Param> inout_twin;
  // std::span<T> u (by value; C++20), with the element's constness.
  QualType span_elem = q->isReferenceType() ? QualType() : L.vector_element(q, "span");
  // A scalar by reference: `const double& dx` (a value, like `double dx`),
  // `DPGEN_OUT double& mass` / `DPGEN_IN const double& c` (a one-element
  // array, Param::scalar_ref).
  // (as a flag and a value: GCC warns, wrongly, that an optional<Type> read
  // under its own test may be uninitialized)
  const std::optional<Type> ref_type =
      q->isReferenceType() ? L.scalar_type(q.getNonReferenceType().getUnqualifiedType())
                           : std::nullopt;
  const bool ref_scalar = ref_type.has_value();
  const Type ref_elem = ref_type.value_or(Type::Bool);
  const CXXRecordDecl* record = q.getNonReferenceType()->getAsCXXRecordDecl();
  if (record && span_elem.isNull() && L.vector_element(q.getNonReferenceType()).isNull() &&
      !record->isLambda()) {
    // An array view (Array4, Kokkos::View, mdspan, ...), or an object
    // of constants (AMReX's Box).
    if (L.views_.is_view_class(record))
      L.views_.view_param(p, ann, out);
    else
      L.objects_.object_param(p, ann, out);
    any_in_ = any_in_ || out.kind == ParamKind::In;
    any_out_ = any_out_ || out.kind == ParamKind::Out;
  } else if (ref_scalar && ref_elem != Type::Bool && (ann == "dpgen.in" || ann == "dpgen.out")) {
    scalar_ref_parameter(p, ann, ref_elem, out);
  } else if (ref_scalar && q.getNonReferenceType().isConstQualified() && ann.empty()) {
    value_parameter(p, ann, out); // const double& dx: read like a value, taken the same way
  } else if (ref_scalar && ann.empty()) {
    L.fail(p->getLocation(), fmt::format("unmarked parameter '{}' is a non-const reference: "
                                       "mark it DPGEN_OUT, or make it const",
                                       out.name), "dpgen-signature");
  } else if (q->isReferenceType() || !span_elem.isNull()) {
    size_param = container_parameter(p, ann, span_elem, out);
  } else if (q->isPointerType()) {
    inout_twin = pointer_parameter(p, ann, out);
  } else {
    value_parameter(p, ann, out);
  }
  out.spelling = out.view ? out.view_type : Lowerer::spelled(p->getType(), /*keep_const=*/true);
  {
    std::string decl;
    llvm::raw_string_ostream os(decl);
    PrintingPolicy policy(L.ctx_.getLangOpts());
    policy.SuppressTagKeyword = true;
    p->getType().getCanonicalType().print(os, policy, out.name);
    out.declaration = os.str();
  }
  L.k_.params.push_back(out);
  // A parameter dpgen adds after this one (`what` it is), unless one of the
  // kernel's already has its name.
  auto add = [&](const std::optional<Param>& extra, const char* what) {
    if (!extra)
      return;
    for (const auto& other : L.k_.params)
      if (other.name == extra->name)
        L.fail(p->getLocation(), fmt::format("parameter '{}' clashes with the {} '{}'",
                                             other.name, what, out.name),
               "dpgen-signature");
    L.k_.params.push_back(*extra);
  };
  add(inout_twin, "name dpgen uses for the new values of in-place array");
  add(size_param, "size dpgen passes for vector");
}

void Signature::tag_parameter(const DeclaratorDecl* p, const std::string& ann, Param& out) {
  // An unnamed parameter of an empty class type (struct XDir {};,
  // std::integral_constant<int, 0>) is a tag choosing an overload; the
  // generated functions take it as well, under a name of their own.
  const CXXRecordDecl* rd = p->getType().getNonReferenceType()->getAsCXXRecordDecl();
  if (!rd || !rd->hasDefinition() || !rd->isEmpty() || !ann.empty())
    L.fail(p->getLocation(), "every kernel parameter needs a name (an unnamed one may only "
                           "be an unannotated tag: a value of an empty class type)",
         "dpgen-signature");
  // Generated code takes it by const reference, so that a declaration of
  // its class is enough: `struct XDir;` (or <type_traits> for
  // std::integral_constant and its aliases).
  std::string type = Lowerer::spelled(p->getType().getNonReferenceType().getUnqualifiedType());
  if (type.rfind("std::integral_constant<", 0) == 0 || type == "std::true_type" ||
      type == "std::false_type") {
    out.tag_declaration = "#include <type_traits>";
  } else if (!isa<ClassTemplateSpecializationDecl>(rd) &&
             rd->getDeclContext()->getRedeclContext()->isFileContext()) {
    std::string decl = fmt::format("{} {};", rd->isClass() ? "class" : "struct",
                                   rd->getNameAsString());
    for (const DeclContext* dc = rd->getDeclContext(); dc; dc = dc->getParent())
      if (const auto* ns = dyn_cast<NamespaceDecl>(dc))
        decl = fmt::format("namespace {} {{ {} }}", ns->getNameAsString(), decl);
    out.tag_declaration = decl;
  } else {
    L.fail(p->getLocation(), fmt::format("tag parameter of type '{}': a tag is a class at "
                                       "namespace scope or a std::integral_constant",
                                       type),
         "dpgen-signature");
  }
  out.kind = ParamKind::Scalar;
  out.tag = true;
  out.elem = Type::Bool; // (no number: never shown or checked)
  out.name = fmt::format("dpgen_tag_{}", llvm::cast<ParmVarDecl>(p)->getFunctionScopeIndex());
  out.elem_name = type;
  out.spelling = "const " + type + "&";
  out.declaration = type + " " + out.name;
  L.k_.params.push_back(out);
}

// `DPGEN_OUT double& mass`, `DPGEN_IN const double& c`: a one-element array
// (Param::scalar_ref).
void Signature::scalar_ref_parameter(const DeclaratorDecl* p, const std::string& ann, Type ref_scalar,
                                     Param& out) {
  QualType q = p->getType();
  QualType elem = q.getNonReferenceType();
  if (!is_real(ref_scalar))
    L.fail(p->getLocation(), fmt::format("{} parameter '{}' must be float or double",
                                       ann == "dpgen.in" ? "DPGEN_IN" : "DPGEN_OUT", out.name),
         "dpgen-signature");
  if (ann == "dpgen.out" && elem.isConstQualified())
    L.fail(p->getLocation(), fmt::format("DPGEN_OUT parameter '{}' is a const reference",
                                       out.name), "dpgen-signature");
  out.kind = ann == "dpgen.in" ? ParamKind::In : ParamKind::Out;
  (ann == "dpgen.in" ? any_in_ : any_out_) = true;
  out.elem = ref_scalar;
  out.elem_name = Lowerer::spelled(elem.getUnqualifiedType());
  out.scalar_ref = true;
}

// std::vector<T>& u or std::span<T> u: the Param, and that of its size.
std::optional<Param> Signature::container_parameter(const DeclaratorDecl* p, const std::string& ann,
                                                    QualType span_elem, Param& out) {
  QualType q = p->getType();
  QualType elem = !span_elem.isNull() ? span_elem : L.vector_element(q.getNonReferenceType());
  if (elem.isNull())
    L.fail(p->getLocation(), fmt::format("parameter '{}' is a reference; pass scalars by value, "
                                       "and arrays as pointers, std::vector<T>& or "
                                       "std::span<T>",
                                       out.name), "dpgen-signature");
  // std::vector<T>& u (or std::span<T> u): elements u[i], size u.size();
  // the generated entry point takes the vectors (spans), its flat twin
  // u.data() and u.size().
  bool is_const = !span_elem.isNull() ? elem.isConstQualified()
                                      : q.getNonReferenceType().isConstQualified();
  elem = elem.getUnqualifiedType();
  out.span = !span_elem.isNull();
  // std::vector<std::vector<T>>& u: rows of their own, u[j][i] (three deep:
  // its elements are no numbers, refused below)
  if (QualType row = out.span ? QualType() : L.vector_element(elem); !row.isNull()) {
    out.nested = true;
    out.row_pointers = true;
    elem = row.getUnqualifiedType();
  }
  auto et = L.scalar_type(elem);
  if (!et || *et == Type::Bool)
    L.fail(p->getLocation(), fmt::format("parameter '{}' holds '{}'; arrays must hold "
                                       "float, double or an integer type",
                                       out.name, elem.getAsString()), "dpgen-signature");
  out.elem = *et;
  out.elem_name = Lowerer::spelled(elem);
  out.container = fmt::format(out.span     ? "std::span<{}>"
                              : out.nested ? "std::vector<std::vector<{}>>"
                                           : "std::vector<{}>",
                              out.elem_name);
  if (ann == "dpgen.inout")
    L.fail(p->getLocation(), fmt::format("DPGEN_INOUT parameter '{}' must be a flat pointer "
                                       "to non-const float or double (pass {}.data())",
                                       out.name, out.name), "dpgen-signature");
  if (ann == "dpgen.in" || ann == "dpgen.out") {
    if (!is_real(*et))
      L.fail(p->getLocation(), fmt::format("{} parameter '{}' must hold float or double",
                                         ann == "dpgen.in" ? "DPGEN_IN" : "DPGEN_OUT",
                                         out.name), "dpgen-signature");
    if (ann == "dpgen.out" && is_const)
      L.fail(p->getLocation(), fmt::format("DPGEN_OUT parameter '{}' is const", out.name), "dpgen-signature");
    out.kind = ann == "dpgen.in" ? ParamKind::In : ParamKind::Out;
    (ann == "dpgen.in" ? any_in_ : any_out_) = true;
  } else {
    if (!is_const)
      L.fail(p->getLocation(), fmt::format("unmarked parameter '{}' is a non-const reference: "
                                         "mark it DPGEN_OUT, or make it const",
                                         out.name), "dpgen-signature");
    out.kind = ParamKind::ConstArray;
  }
  Param sz;
  sz.name = out.name + "_size";
  sz.kind = ParamKind::Scalar;
  sz.elem = Type::Int;
  sz.elem_name = sz.spelling = "unsigned long";
  sz.synthetic = true;
  sz.is_unsigned = true;
  return sz;
}

// A pointer: flat, rows (double (*a)[64], a[][64], a C VLA row), row pointers
// (double**, double***); the twin of a DPGEN_INOUT array, if one.
std::optional<Param> Signature::pointer_parameter(const DeclaratorDecl* p, const std::string& ann,
                                                  Param& out) {
  QualType q = p->getType();
  QualType elem = q->getPointeeType();
  // Rows of a multi-dimensional array: double (*a)[64], double a[][64],
  // or, in C, double a[n][n] (a variable-length row: flat in the
  // generated signature).
  bool const_rows = elem.isConstQualified();
  while (const clang::ArrayType* at = L.ctx_.getAsArrayType(elem)) {
    if (const auto* c = dyn_cast<ConstantArrayType>(at))
      out.rows += fmt::format("[{}]", c->getSize().getZExtValue());
    else if (!isa<VariableArrayType>(at))
      L.fail(p->getLocation(), fmt::format("parameter '{}' has an array type outside the "
                                         "kernel subset",
                                         out.name), "dpgen-signature");
    elem = at->getElementType();
    const_rows = const_rows || elem.isConstQualified();
  }
  if (const_rows)
    elem.addConst();
  if (elem->isPointerType() && out.rows.empty()) {
    // double** a, const double* const* a: rows through pointers, each
    // row an array of its own (documented assumption).
    elem = elem->getPointeeType();
    if (elem->isPointerType()) { // double*** a: planes of rows
      elem = elem->getPointeeType();
      out.plane_pointers = true;
    }
    if (elem->isPointerType() || L.ctx_.getAsArrayType(elem))
      L.fail(p->getLocation(),
           fmt::format("parameter '{}' ('{}') has more than two levels of row pointers: "
                       "pass 'double** {}' (a[j][i]), 'double*** {}' (a[k][j][i]) or a "
                       "flat pointer indexed {}[(k * ny + j) * nx + i]",
                       out.name, q.getAsString(), out.name, out.name, out.name), "dpgen-signature");
    if (ann == "dpgen.inout")
      L.fail(p->getLocation(), fmt::format("DPGEN_INOUT parameter '{}' must be a flat "
                                         "pointer to non-const float or double",
                                         out.name), "dpgen-signature");
    out.row_pointers = true;
  } else if (elem->isPointerType()) {
    L.fail(p->getLocation(), fmt::format("parameter '{}' ('{}') mixes fixed-length rows and "
                                       "row pointers, outside the kernel subset",
                                       out.name, q.getAsString()), "dpgen-signature");
  }
  auto et = L.scalar_type(elem);
  // (a bool mask, `const bool* solid`, is a constant array: not differentiated)
  if (!et || (*et == Type::Bool && (!ann.empty() && ann != "dpgen.const")))
    L.fail(p->getLocation(), fmt::format("parameter '{}' points to '{}'; arrays must hold "
                                       "float, double or an integer type (or bool, "
                                       "for an unmarked mask)",
                                       out.name,
                                       elem.getAsString(PrintingPolicy(L.ctx_.getLangOpts()))),
         "dpgen-signature");
  out.elem = *et;
  out.elem_name = Lowerer::spelled(elem);
  if (ann == "dpgen.in") {
    if (!is_real(*et))
      L.fail(p->getLocation(), fmt::format("DPGEN_IN parameter '{}' must point to float or "
                                         "double, not '{}'",
                                         out.name, elem.getAsString()), "dpgen-signature");
    out.kind = ParamKind::In;
    any_in_ = true;
  } else if (ann == "dpgen.inout") {
    if (!is_real(*et) || elem.isConstQualified() || !out.rows.empty())
      L.fail(p->getLocation(), fmt::format("DPGEN_INOUT parameter '{}' must be a flat pointer "
                                         "to non-const float or double",
                                         out.name), "dpgen-signature");
    out.kind = ParamKind::In;
    out.inout = true;
    any_in_ = any_out_ = true;
    Param twin;
    twin.name = out.name + "_new";
    twin.kind = ParamKind::Out;
    twin.elem = *et;
    twin.elem_name = out.elem_name;
    twin.twin_of = out.name;
    twin.declaration = twin.spelling = fmt::format("{}* {}", out.elem_name, twin.name);
    return twin;
  } else if (ann == "dpgen.out") {
    if (!is_real(*et))
      L.fail(p->getLocation(), fmt::format("DPGEN_OUT parameter '{}' must point to float or "
                                         "double, not '{}'",
                                         out.name, elem.getAsString()), "dpgen-signature");
    if (elem.isConstQualified())
      L.fail(p->getLocation(), fmt::format("DPGEN_OUT parameter '{}' points to const", out.name), "dpgen-signature");
    out.kind = ParamKind::Out;
    any_out_ = true;
  } else {
    out.kind = ParamKind::ConstArray;
  }
  return std::nullopt;
}

// A scalar by value (or a const reference to one, read alike).
void Signature::value_parameter(const DeclaratorDecl* p, const std::string& ann, Param& out) {
  QualType q = p->getType().getNonReferenceType();
  auto t = L.scalar_type(q);
  if (!t)
    L.fail(p->getLocation(), fmt::format("parameter '{}' has type '{}', outside the kernel "
                                       "subset",
                                       out.name, q.getAsString()), "dpgen-signature");
  if (!ann.empty() && ann != "dpgen.const")
    L.fail(p->getLocation(), fmt::format("'{}' is a scalar: DPGEN_IN/DPGEN_OUT mark pointer "
                                       "parameters (pass a one-element array to "
                                       "differentiate a scalar)",
                                       out.name), "dpgen-signature");
  out.kind = ParamKind::Scalar;
  out.elem = *t;
  out.elem_name = Lowerer::spelled(q);
  out.is_unsigned = *t == Type::Int && q->isUnsignedIntegerType();
  // an enum (`Bc bc`, `const Bc& bc`): the generated declarations name its
  // type, so they include the header that declares it
  out.enum_value = q.getCanonicalType()->isEnumeralType();
  if (const auto* et = q.getCanonicalType()->getAs<EnumType>())
    out.tag_declaration = L.views_.include_for(et->getDecl(), p->getLocation(),
                                               fmt::format("parameter '{}'", out.name));
}

// The parameters keep their names in every generated function, so a name
// the generated code needs for something else is an error: the adjoint or
// tangent of another parameter (<array>_adj, <array>_dot), the size dpgen
// passes for a vector, the prefix dpgen_, a C++ keyword.
void Signature::check_parameter_names() {
  for (const ParmVarDecl* decl : L.fn_->parameters()) {
    std::string name = decl->getNameAsString();
    if (const Param* a = L.contract_name_of(name))
      L.error(decl->getLocation(),
            fmt::format("parameter '{}' has the name that the generated {} gives the {} of "
                        "array '{}'; rename it",
                        name, name.back() == 'j' ? "adjoint" : "tangent",
                        name.back() == 'j' ? "adjoint" : "tangent", a->name), "dpgen-name");
    else if (name.rfind("dpgen_", 0) == 0)
      L.error(decl->getLocation(), fmt::format("parameter '{}': names starting with 'dpgen_' "
                                             "are reserved for generated code; rename it",
                                             name), "dpgen-name");
    else if (L.is_cxx_only_keyword(name))
      L.error(decl->getLocation(), fmt::format("parameter '{}' is a C++ keyword, and the "
                                             "generated adjoint is C++; rename it",
                                             name), "dpgen-name");
  }
  for (const auto& p : L.k_.params)
    if (p.synthetic)
      for (const auto& other : L.k_.params)
        if (!other.synthetic && other.name == p.name)
          for (const ParmVarDecl* decl : L.fn_->parameters())
            if (decl->getNameAsString() == p.name)
              L.error(decl->getLocation(),
                    fmt::format("parameter '{}' clashes with the size dpgen passes for vector "
                                "'{}'; rename it",
                                p.name, p.name.substr(0, p.name.size() - 5)), "dpgen-name");
}

// The members of the kernel's class it names through `this` (lower_impl.hpp).
std::set<const FieldDecl*> Signature::used_fields() const {
  std::set<const FieldDecl*> out;
  std::set<const FunctionDecl*> seen;
  std::function<void(const Stmt*)> walk = [&](const Stmt* s) {
    if (!s)
      return;
    if (const auto* mc = dyn_cast<CXXMemberCallExpr>(s)) // a method on this: its body too
      if (const CXXMethodDecl* md = mc->getMethodDecl();
          md && md->getParent() == L.self_class_ && md->hasBody() &&
          isa<CXXThisExpr>(mc->getImplicitObjectArgument()->IgnoreParenImpCasts()) &&
          seen.insert(md).second)
        walk(md->getBody());
    if (const auto* m = dyn_cast<MemberExpr>(s))
      if (const auto* f = dyn_cast<FieldDecl>(m->getMemberDecl());
          f && f->getParent() == L.self_class_ &&
          isa<CXXThisExpr>(m->getBase()->IgnoreParenImpCasts()))
        out.insert(f);
    if (const auto* le = dyn_cast<LambdaExpr>(s))
      walk(le->getBody());
    for (const Stmt* c : s->children())
      walk(c);
  };
  walk(L.fn_->getBody());
  // the class's call operators (a functor run by a parallel-for on *this)
  for (const CXXMethodDecl* m : L.self_class_->methods())
    if (m->isOverloadedOperator() && m->getOverloadedOperator() == OO_Call && m->hasBody())
      walk(m->getBody());
  return out;
}

} // namespace dpgen::lowering
