// Emit (phase 6), the staged adjoint: a kernel whose later loop nests read
// what earlier ones wrote (work arrays). One adjoint per nest, run backwards
// by a driver that recomputes the work arrays first (with the user's kernel,
// or a forward printed from the IR: emit_forward.cpp), in flat buffers or,
// for view outputs, in dpgen::ViewBuffers laid out like their seeds; and the
// prologue of an in-place array's adjoint.
#include "emit_checked.hpp"
#include "emit_forward.hpp"
#include "emit_impl.hpp"
#include "ir_walk.hpp"
#include "print.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <map>
#include <set>

namespace dpgen::adjoint {

namespace {

// `T* name` for a parameter of the forward kernel's declaration.
std::string forward_params(const Kernel& k) {
  std::vector<std::string> ps;
  for (const auto& p : k.params)
    if (!p.synthetic && !p.global && !p.returned)
      ps.push_back(p.declaration);
  return fmt::format("{}", fmt::join(ps, ", "));
}

// For each nest, its loops around what `lines` gives for each of its stores
// (nothing: the store is skipped, and a nest without lines is left out),
// each under the store's path, with the locals of the path and of `uses`
// defined first. Serial, in the driver's scope (its parameters and the
// kernel's locals).
using StoreLines = std::function<std::vector<std::string>(const Store&, std::vector<ExprP>& uses)>;
void over_stores(Code& code, const Kernel& k, const StoreLines& lines) {
  for (const auto& nest : k.nests) {
    std::vector<std::pair<const Store*, std::vector<std::string>>> todo;
    std::vector<std::vector<ExprP>> needs;
    for (const auto& s : nest.stores) {
      std::vector<ExprP> uses;
      auto ls = lines(s, uses);
      if (ls.empty())
        continue;
      todo.emplace_back(&s, std::move(ls));
      needs.push_back(std::move(uses));
    }
    if (todo.empty())
      continue;
    code.open("");
    int opened = 1;
    for (const auto& l : nest.loops) {
      code.open(fmt::format("for ({} {} = {}; {} < {}; ++{})", kCellType, l.var, print(l.lo),
                            l.var, print(l.hi), l.var));
      ++opened;
    }
    std::set<int> done;
    std::set<std::string> vars;
    for (size_t t = 0; t < todo.size(); ++t) {
      const Store& s = *todo[t].first;
      const auto& ls = todo[t].second;
      std::map<int, LocalP> candidates, locals;
      for (const auto& pc : s.path)
        collect(pc.cond, candidates, vars);
      for (const auto& e : needs[t])
        collect(e, candidates, vars);
      // only those the printed lines name (an index prints its affine locals
      // expanded), and what their definitions name in turn
      std::string text = s.path.empty() ? "" : conjunction(s.path);
      for (const auto& l : ls)
        text += " " + l;
      for (bool grew = true; grew;) {
        grew = false;
        for (const auto& [id, l] : candidates)
          if (!locals.count(id) && names_identifier(text, l->name)) {
            locals[id] = l;
            text += " " + print(l->def);
            grew = true;
          }
      }
      define_locals(code, locals, done);
      if (s.path.empty()) {
        for (const auto& l : ls)
          code.line("{}", l);
      } else if (ls.size() == 1) {
        code.line("if ({}) {}", conjunction(s.path), ls.front());
      } else {
        code.open(fmt::format("if ({})", conjunction(s.path)));
        for (const auto& l : ls)
          code.line("{}", l);
        code.close();
      }
    }
    for (int i = 0; i < opened; ++i)
      code.close();
  }
}

// The reads of view work arrays in `e` (locals' definitions included).
std::vector<ExprP> view_work_reads(const Kernel& k, const ExprP& e) {
  std::vector<ExprP> out;
  std::set<const LocalVar*> seen;
  walk(
      e,
      [&](const ExprP& x) {
        if (x->op == Op::Read && x->shape.view && k.intermediates.count(x->name))
          out.push_back(x);
        return true;
      },
      [](const ExprP&) { return true; }, seen);
  return out;
}

// The buffers of view outputs (ViewBuffer, laid out like the seed) cover
// every element the kernel stores, and for a work array every element a
// later loop reads: found by running the loops, before the forward
// (check_extents.cpp: view_outputs_located says where they run depends on inputs
// only).
void emit_view_cover(Code& code, const Kernel& k, const std::function<std::string(const std::string&)>& v_of) {
  code.line("// The elements the view outputs' buffers hold: where the kernel stores them, and");
  code.line("// where a later loop reads a work array.");
  over_stores(code, k, [&](const Store& s, std::vector<ExprP>& uses) {
    std::vector<std::string> ls;
    auto cover = [&](const std::string& array, const ExprP& index, Shape shape) {
      std::string l = fmt::format("{}.cover{};", v_of(array), subscript(index, shape));
      if (std::find(ls.begin(), ls.end(), l) == ls.end())
        ls.push_back(l);
      uses.push_back(index);
    };
    const Param* out = k.find_param(s.array);
    if (out && out->view)
      cover(s.array, s.index, shape_of(*out));
    for (const auto& r : view_work_reads(k, s.value))
      cover(r->name, r->ops[0], r->shape);
    return ls;
  });
}

} // namespace

// The adjoint has no output view, only its seed, of the same shape and
// bounds: what the kernel reads of an output view's shape (`un.cols()`,
// `amrex::lbound(un)`) it reads of the seed (ir.hpp: RenameScope). In a
// stage of a staged adjoint a work array's seed is a buffer, laid out like
// the seed's view (`flux_adj.view().cols()`).
std::map<std::string, std::string> seed_names(const Kernel& k, bool stage) {
  std::map<std::string, std::string> out;
  for (const auto& p : k.params)
    if (p.view && p.kind == ParamKind::Out)
      out[p.name] = p.name + (stage && k.intermediates.count(p.name) ? "_adj.view()" : "_adj");
  return out;
}

// A kernel whose later loop nests read what earlier ones wrote (work
// arrays): one adjoint per nest, run in reverse order. The driver recomputes
// the work arrays with the forward kernel (into buffers, NaN where the
// kernel writes nothing), seeds them with their own seeds, and lets each
// nest's adjoint add to them before the nest that wrote them reads them.
void emit_staged(Code& code, const LoopPlan& plan, const std::string& fn_name) {
  const Kernel& k = *plan.adjoint->kernel;
  const std::vector<Stage>& stages = plan.adjoint->stages; // schedule.cpp
  code.raw("namespace {\n");
  // A nest whose stores have no derivative (a min/max reduction's scan and
  // ties, lower_impl.hpp; a store of constants) has no adjoint stage.
  auto idle = [&](size_t j) {
    return stages[j].plan->gathers.empty() && stages[j].plan->scatters.empty();
  };
  for (size_t j = 0; j < stages.size(); ++j) {
    const Kernel& s = *stages[j].kernel;
    if (idle(j))
      continue;
    code.line("// Adjoint of loop nest {} of {} ({}:{}).", j + 1, k.name, base_name(k.file),
              s.nests.front().stores.front().pos.line);
    RenameScope seeds(seed_names(k, true));
    code.open(fmt::format("void {}_adjoint({})", s.name, param_list(s, false)));
    emit_body(code, plan.stages[j]);
    code.close();
    code.raw("\n");
  }
  const std::string recompute = k.fresh(k.name + "_recompute");
  // The accumulators' sums (the user's kernel keeps them to itself), and an
  // in-place array's old values (the user's kernel would overwrite them):
  // recomputed by the forward as the IR says, into buffers.
  // A view output, too: the user's kernel could only write it through a
  // view, and dpgen cannot make one over a buffer (dpgen/view_buffer.hpp).
  // And every array of a kernel with std::vector parameters: the user's kernel takes the
  // containers, the adjoint's flat part their data.
  const bool own_forward = !k.hidden.empty() || has_inout(k) ||
                           std::any_of(k.params.begin(), k.params.end(), [](const Param& p) {
                             return (p.view && !p.global) || !p.container.empty();
                           });
  if (own_forward)
    emit_recompute(code, plan.forward, recompute);
  code.raw("} // namespace\n\n");
  if (!own_forward) {
    code.line("// The forward kernel, which recomputes the work arrays.");
    code.line("{}void {}({});", k.c_linkage ? "extern \"C\" " : "", k.name, forward_params(k));
    code.raw("\n");
  }
  code.line("// Adjoint of {} ({}:{}): its loop nests backwards; the work arrays {} are "
            "recomputed first.",
            k.name, base_name(k.file), k.pos.line,
            fmt::join(k.intermediates.begin(), k.intermediates.end(), ", "));
  code.open(fmt::format("void {}({})", fn_name, param_list(k, false)));
  define_kernel_locals(code, k);
  emit_size_checks(code, k, k.name + "_adjoint");
  emit_container_reach_checks(code, k, k.name + "_adjoint");
  // Buffers of the outputs' recomputed values (<out>_v) and of the work
  // arrays' adjoints (<out>_b), <out>_n elements each (Kernel::fresh names).
  auto n_of = [&](const std::string& a) { return k.fresh(a + "_n"); };
  auto v_of = [&](const std::string& a) { return k.fresh(a + "_v"); };
  auto b_of = [&](const std::string& a) { return k.fresh(a + "_b"); };
  std::vector<std::string> fwd, flat;
  std::vector<const Param*> view_outs;
  for (const auto& p : k.params) {
    if (p.global)
      continue;
    if (p.kind == ParamKind::Out && p.view) {
      code.line("// '{}' recomputed, in a buffer laid out like its seed", p.name);
      code.line("{} {}({}_adj);", view_buffer_type(p), v_of(p.name), p.name);
      view_outs.push_back(&p);
      flat.push_back(v_of(p.name));
      flat.push_back(p.name + "_adj"); // (its shape, for what the kernel reads of it)
    } else if (p.kind == ParamKind::Out) {
      code.line("const std::ptrdiff_t {} = {};", n_of(p.name), k.extent.at(p.name).code());
      code.line("std::vector<{}> {}(static_cast<std::size_t>({}), "
                "std::numeric_limits<{}>::quiet_NaN());",
                p.elem_name, v_of(p.name), n_of(p.name), p.elem_name);
      if (k.intermediates.count(p.name) && p.container.empty()) {
        code.line("std::vector<{}> {}({}_adj, {}_adj + {}); // its seed, then more", p.elem_name,
                  b_of(p.name), p.name, p.name, n_of(p.name));
      } else if (k.intermediates.count(p.name)) {
        // (a vector's seed as long as it is: the buffer's extent may pass the vector where
        // the kernel's writes are conditional, and the kernel writes nothing there)
        code.line("std::vector<{}> {}(static_cast<std::size_t>({})); // its seed, then more",
                  p.elem_name, b_of(p.name), n_of(p.name));
        code.line("std::copy_n({}_adj, std::min<std::ptrdiff_t>({}, static_cast<std::ptrdiff_t>("
                  "{}_size)), {}.begin());",
                  p.name, n_of(p.name), p.name, b_of(p.name));
      }
      std::string data = v_of(p.name) + ".data()";
      flat.push_back(data);
      fwd.push_back(p.rows.empty() ? data
                                   : fmt::format("reinterpret_cast<{} (*){}>({})", p.elem_name,
                                                 p.rows, data));
    } else if (p.kind == ParamKind::In && p.rows.empty() && !p.view && !p.scalar_ref &&
               p.container.empty() && p.declaration.rfind("const ", 0) != 0) {
      // an input the kernel declares as `double* state` (no const): the
      // adjoint takes it as `const double*`, and the kernel does not write it
      fwd.push_back(fmt::format("const_cast<{}*>({})", p.elem_name, p.name));
      if (p.twin_of.empty())
        flat.push_back(p.name);
    } else if (p.kind == ParamKind::Scalar || p.rows.empty()) {
      fwd.push_back(p.name);
      if (p.twin_of.empty())
        flat.push_back(p.name);
    } else {
      fwd.push_back(fmt::format("reinterpret_cast<const {} (*){}>({})", p.elem_name, p.rows,
                                p.name));
      flat.push_back(p.name);
    }
  }
  if (!view_outs.empty()) {
    emit_view_cover(code, k, v_of);
    for (const Param* p : view_outs) {
      code.line("{}.allocate(std::numeric_limits<{}>::quiet_NaN());", v_of(p->name), p->elem_name);
      if (!k.intermediates.count(p->name))
        continue;
      code.line("// the adjoint of '{}': its seed (below), then more", p->name);
      code.line("{} {}({}_adj);", view_buffer_type(*p), b_of(p->name), p->name);
      code.line("{}.cover_as({});", b_of(p->name), v_of(p->name));
      code.line("{}.allocate(0);", b_of(p->name));
    }
  }
  for (const auto& h : k.hidden) {
    code.line("const std::ptrdiff_t {} = {}; // {} '{}'", n_of(h.name), k.extent.at(h.name).code(),
              is_buffer(h) ? "the rows of line buffer" : "the sums of", h.spelling);
    code.line("std::vector<{}> {}(static_cast<std::size_t>({}), "
              "std::numeric_limits<{}>::quiet_NaN());",
              h.elem_name, v_of(h.name), n_of(h.name), h.elem_name);
    code.line("std::vector<{}> {}(static_cast<std::size_t>({})); // their adjoints", h.elem_name,
              b_of(h.name), n_of(h.name));
    flat.push_back(v_of(h.name) + ".data()");
  }
  if (!own_forward)
    code.line("{}({});", k.name, fmt::join(fwd, ", "));
  else
    code.line("{}({});", recompute, fmt::join(flat, ", "));
  if (std::any_of(view_outs.begin(), view_outs.end(),
                  [&](const Param* p) { return k.intermediates.count(p->name) > 0; })) {
    code.line("// The seeds of the view work arrays, where the kernel stores them.");
    over_stores(code, k, [&](const Store& s, std::vector<ExprP>& uses) -> std::vector<std::string> {
      const Param* p = k.find_param(s.array);
      if (!p || !p->view || !k.intermediates.count(s.array))
        return {};
      uses.push_back(s.index);
      const std::string at = subscript(s.index, shape_of(*p));
      return {fmt::format("{}{} = {}_adj{};", b_of(s.array), at, s.array, at)};
    });
  }
  for (size_t j = stages.size(); j-- > 0;) {
    const Kernel& s = *stages[j].kernel;
    if (idle(j))
      continue;
    std::vector<std::string> args;
    for (const auto& p : s.params) {
      if (p.global) // (in no parameter list: param_list; the stage reads the global)
        continue;
      bool work = k.intermediates.count(p.name) > 0;
      switch (p.kind) {
      case ParamKind::In: // (a view's buffers are passed as they are)
        args.push_back(work ? v_of(p.name) + (p.view ? "" : ".data()") : p.name);
        args.push_back(work ? b_of(p.name) + (p.view ? "" : ".data()") : p.name + "_adj");
        break;
      case ParamKind::Out:
        args.push_back(work ? b_of(p.name) + (p.view ? "" : ".data()") : p.name + "_adj");
        break;
      case ParamKind::ConstArray:
      case ParamKind::Scalar:
        args.push_back(p.name);
        break;
      }
    }
    code.line("{}_adjoint({});", s.name, fmt::join(args, ", "));
  }
  code.close();
}

// An in-place array u: on entry u_adj holds the seed of its new values, on
// return the adjoint of its old ones. The flat adjoint sees u as an input and
// its new values as the output u_new: so u_adj starts as 0 where the kernel
// writes u (the old value reaches the new one only through the kernel) and
// as the seed elsewhere (an element the kernel leaves is passed through).
void emit_inout_prologue(Code& code, const Kernel& k) {
  if (!has_inout(k))
    return;
  define_kernel_locals(code, k);
  for (const auto& p : k.params) {
    if (!p.inout)
      continue;
    const std::string twin = p.name + "_new";
    code.line("// '{}' is updated in place: {}_adj holds the seed of its new values on entry",
              p.name, p.name);
    code.line("// and the adjoint of its old values on return.");
    // (the seed is taken at the elements the kernel stores, under the stores' conditions:
    // nothing is read that the kernel does not write, and each element once, as the
    // kernel stores it once)
    const std::string n = k.fresh(p.name + "_n");
    code.line("const std::ptrdiff_t {} = {};", n, k.extent.at(twin).code());
    code.line("std::vector<{}> {}(static_cast<std::size_t>({}));", p.elem_name,
              seed_buffer(k, p.name), n);
    over_stores(code, k, [&](const Store& s, std::vector<ExprP>& uses) -> std::vector<std::string> {
      if (s.array != twin)
        return {};
      uses.push_back(s.index);
      const std::string at = subscript(s.index, shape_of(p));
      return {fmt::format("{}{} = {}_adj{};", seed_buffer(k, p.name), at, p.name, at),
              fmt::format("{}_adj{} = 0;", p.name, at)};
    });
  }
}

} // namespace dpgen::adjoint
