// Lowering, line buffers: a part of the lowering with its own state (the
// buffers declared so far, the extents of pointers to arrays). The statement
// lowering declares buffers (declare_buffer, declare_array_pointer), the
// element lowering maps a buffer's element to its hidden array's
// (buffer_index) and has each store and read checked (check_buffer_store,
// check_buffer_read). Included by lower_impl.hpp only; lower_buffer.cpp
// says what a buffer is.
#pragma once

#include "affine.hpp"
#include "ir.hpp"
#include "prove.hpp"

#include <clang/AST/Type.h>
#include <clang/Basic/SourceLocation.h>

#include <algorithm>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace clang {
class Expr;
class ForStmt;
class VarDecl;
} // namespace clang

namespace dpgen::lowering {

class Lowerer;

// A local array of more than 64 elements or of a run-time length (`double
// u1[M]`, `double tmp[nx]`) is a hidden work array with one row of its
// length per iteration of the loops around all its uses (its row loops):
// `tmp[e]` is the element row * length + e. Each element is written with
// '=' once per row, inside the buffer, and read only after an earlier loop
// of the same row wrote it (or the same iteration stored it).
class LineBuffers {
public:
  explicit LineBuffers(Lowerer& lowerer) : L(lowerer) {}

  // `array` (a hidden array) is a line buffer's.
  bool is_buffer(const std::string& array) const { return buffers_.count(array) != 0; }
  // `double u1[M]` (M > 64), `double tmp[nx]`, `std::array<double, 200> t`:
  // its hidden array (Kernel::hidden) and the local's binding to it.
  // `sized`: a std::vector's (count) or (count, value) constructor (declare_vector).
  void declare_buffer(const clang::VarDecl* v, clang::QualType elem, ExprP length,
                      bool sized = false);
  // `std::vector<double> flux(n + 1);` (or `(n + 1, 0.0)`), a local: a line buffer of that
  // length. False if `v` is no such vector.
  bool declare_vector(const clang::VarDecl* v);
  // `v` is a line buffer (the kernel assigns its elements, never its length).
  bool declares(const clang::VarDecl* v) const {
    return std::any_of(buffers_.begin(), buffers_.end(),
                       [&](auto& b) { return b.second.decl == v; });
  }
  // The length of `p`'s line buffer (a row's elements: `flux.size()`); null for another array.
  ExprP length_of(const Param* p) const {
    return p && buffer_of(p->name) ? buffer_of(p->name)->length : nullptr;
  }
  // The flat element of index `local` of buffer `p` in this iteration.
  ExprP buffer_index(const Param* p, const ExprP& local, const clang::Expr* at);
  // A store at / read of buffer `p`'s flat element `flat`: in bounds, written
  // once per row with '=', read after it is written (errors otherwise, or
  // run-time checks where only the sizes decide).
  void check_buffer_store(const Param* p, const ExprP& flat, bool accumulate,
                          const clang::Expr* lhs);
  // An uncovered read of a std::vector made in its row (`flux(n + 1, 0.0)`; earlier stores all
  // known intervals, none in a loop around the read, the element inside): `value` where `in`
  // (in an interval) fails, or everywhere if `in` is null. Neither: the read sees a store.
  struct BufferRead {
    ExprP in, value;
  };
  BufferRead check_buffer_read(const Param* p, const ExprP& flat, const clang::Expr* e);
  // `double (*u)[n][n] = (double (*)[n][n]) u_flat;`: u names the parameter.
  // False if `v` is no such pointer.
  bool declare_array_pointer(const clang::VarDecl* v);
  // The extent of such a pointer's variable array type `size` (its size
  // expression), as evaluated at the declaration; null if it has none.
  ExprP vla_size(const clang::Expr* size) const {
    auto it = vla_sizes_.find(size);
    return it == vla_sizes_.end() ? nullptr : it->second;
  }

private:
  Lowerer& L;

  struct Buffer {
    const clang::VarDecl* decl = nullptr;
    std::string array;              // the hidden array
    ExprP length;                   // elements per row
    std::vector<int> decl_loop_ids; // the loops around the declaration
    // The counters of the loops (`for`, and `while` loops that count) between the
    // declaration and the innermost statement that holds every use, outermost first (null:
    // a loop with no counter, which no use can be placed in).
    std::vector<const clang::VarDecl*> row_counters;
    bool placed = false; // row loops fixed (at the first use)
    size_t depth = 0;    // how many loops of the kernel are row loops
    std::vector<int> row_ids;
    ExprP row;
    ExprP fill; // a std::vector's value (zero, or the one it is made with); null for arrays
  };
  std::map<std::string, Buffer> buffers_; // by hidden array
  const Buffer* buffer_of(const std::string& array) const;
  std::optional<Poly> buffer_local(const Buffer& b, const ExprP& flat) const;
  bool read_inside(const Buffer& b, const Poly& local, Facts facts, const clang::Expr* e);
  Facts facts_here() const;
  bool holds_here(const PathCond& pc, const Facts& facts) const;
  std::vector<SizeCond> premises_here() const;
  bool prove_or_check(const std::vector<Poly>& goals, const Facts& facts, const std::string& what,
                      clang::SourceLocation loc, bool& never);
  // The extents of pointers to arrays' variable array types, as evaluated at
  // their declaration (element() reads them there).
  std::map<const clang::Expr*, ExprP> vla_sizes_;
};

} // namespace dpgen::lowering
