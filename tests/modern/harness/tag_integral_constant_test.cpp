#include "corpus_check.hpp"

#include "tag_integral_constant.cpp"
#include "tag_integral_constant_adjoint.hpp"
#if CORPUS_TANGENT
#include "tag_integral_constant_tangent.hpp"
#endif

using namespace corpus;

template <class Face> void check_faces() {
  for (auto [nx, ny] : {std::pair{1, 1}, {4, 3}}) {
    const size_t N = size_t(nx * ny);
    Problem<double> p;
    p.in_sizes = {N};
    p.in_ranges = {{0.5, 2.0}};
    p.out_sizes = {N};
    p.forward = [&](auto in, auto out) { face_conductivity(in[0], out[0], nx, ny, Face{}); };
    p.adjoint = [&](auto in, auto adj, auto seed) {
      face_conductivity_adjoint(in[0], adj[0], seed[0], nx, ny, Face{});
    };
#if CORPUS_TANGENT
    p.tangent = [&](auto in, auto d, auto out, auto dout) {
      face_conductivity_tangent(in[0], d[0], out[0], dout[0], nx, ny, Face{});
    };
#endif
    check_adjoint(p);
  }
}

TEST_CASE("modern: face_conductivity(XFace)") { check_faces<XFace>(); }
TEST_CASE("modern: face_conductivity(YFace)") { check_faces<YFace>(); }
