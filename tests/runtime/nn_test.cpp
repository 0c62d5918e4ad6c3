// Tests of dpgen/nn.hpp: each layer's adjoint by the dot-product test (linear maps) or central
// differences (activations), convolution indexing, network gradients vs finite differences,
// deterministic initialization, and training the flat parameter vector with an optimizer.
#include "dpgen/nn.hpp"
#include "dpgen/train.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <random>
#include <string>

namespace {

using Eigen::VectorXd;

VectorXd random_vector(Eigen::Index n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal;
  VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i)
    v[i] = normal(rng);
  return v;
}

VectorXd apply(const dpgen::Layer& layer, const VectorXd& params, const VectorXd& x) {
  VectorXd y(layer.output_size());
  layer.forward(params, x, y);
  return y;
}

// Zeroes the biases, the last `biases` entries: the layer is then linear in x.
VectorXd without_biases(VectorXd params, Eigen::Index biases) {
  params.tail(biases).setZero();
  return params;
}

// <J v, w> == <v, J^T w> for a layer's two Jacobians. Both are exact linear maps here: in x
// with the biases zeroed (J_x v = layer(v; p)), and in the parameters (y is linear in (W, b),
// so J_p v = layer(x; v)). Tolerance: 1e-12 relative to |J v| |w|, the scale of both sides.
void dot_product_test(const dpgen::Layer& layer, Eigen::Index biases, unsigned seed) {
  const VectorXd p = random_vector(layer.parameter_count(), seed);
  const VectorXd x = random_vector(layer.input_size(), seed + 1);
  const VectorXd v_x = random_vector(layer.input_size(), seed + 2);
  const VectorXd v_p = random_vector(layer.parameter_count(), seed + 3);
  const VectorXd w = random_vector(layer.output_size(), seed + 4);
  const VectorXd p0 = without_biases(p, biases);

  VectorXd x_adj = VectorXd::Zero(layer.input_size());
  VectorXd p_adj = VectorXd::Zero(layer.parameter_count());
  layer.backward(p0, x, apply(layer, p0, x), w, x_adj, p_adj);
  const VectorXd jx_v = apply(layer, p0, v_x);
  CHECK(std::abs(jx_v.dot(w) - v_x.dot(x_adj)) <= 1e-12 * jx_v.norm() * w.norm());

  const VectorXd jp_v = apply(layer, v_p, x);
  CHECK(std::abs(jp_v.dot(w) - v_p.dot(p_adj)) <= 1e-12 * jp_v.norm() * w.norm());

  // The adjoint accumulates: a second call adds the same amounts again.
  VectorXd x_adj2 = x_adj, p_adj2 = p_adj;
  layer.backward(p0, x, apply(layer, p0, x), w, x_adj2, p_adj2);
  CHECK((x_adj2 - 2.0 * x_adj).norm() <= 1e-14 * x_adj.norm());
  CHECK((p_adj2 - 2.0 * p_adj).norm() <= 1e-14 * p_adj.norm());
}

// Central differences: <(f(x + e v) - f(x - e v)) / 2e, w> against <v, J^T w>.
void activation_test(const dpgen::Layer& layer, const VectorXd& x, unsigned seed) {
  const VectorXd none;
  const VectorXd v = random_vector(x.size(), seed), w = random_vector(x.size(), seed + 1);
  const double eps = 1e-6;
  const VectorXd jv =
      (apply(layer, none, x + eps * v) - apply(layer, none, x - eps * v)) / (2 * eps);
  VectorXd x_adj = VectorXd::Zero(x.size()), p_adj;
  layer.backward(none, x, apply(layer, none, x), w, x_adj, p_adj);
  CHECK(jv.dot(w) == doctest::Approx(v.dot(x_adj)).epsilon(1e-6));
}

// L(p, x) = 1/2 |net(p, x) - target|^2.
double loss(const dpgen::Sequential& net, const VectorXd& p, const VectorXd& x,
            const VectorXd& target) {
  return 0.5 * (net(p, x) - target).squaredNorm();
}

// Checks dL/dp and dL/dx from backward() against central differences, coordinate by coordinate.
void network_gradient_test(const dpgen::Sequential& net, std::uint64_t seed) {
  const VectorXd p = net.initialize(seed);
  const VectorXd x = random_vector(net.input_size(), 91);
  const VectorXd target = random_vector(net.output_size(), 92);
  dpgen::Sequential::Activations acts;
  net.forward(p, x, acts);
  VectorXd x_adj, p_adj;
  net.backward(p, acts, acts.output() - target, x_adj, p_adj);

  const double eps = 1e-6;
  VectorXd fd_p(p.size()), fd_x(x.size()), q = p, y = x;
  for (Eigen::Index i = 0; i < p.size(); ++i) {
    q[i] = p[i] + eps;
    const double up = loss(net, q, x, target);
    q[i] = p[i] - eps;
    fd_p[i] = (up - loss(net, q, x, target)) / (2 * eps);
    q[i] = p[i];
  }
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    y[i] = x[i] + eps;
    const double up = loss(net, p, y, target);
    y[i] = x[i] - eps;
    fd_x[i] = (up - loss(net, p, y, target)) / (2 * eps);
    y[i] = x[i];
  }
  // Truncation O(eps^2) and rounding O(1e-16 / eps) leave about 1e-9 relative.
  CHECK((p_adj - fd_p).norm() <= 1e-7 * fd_p.norm());
  CHECK((x_adj - fd_x).norm() <= 1e-7 * fd_x.norm());
}

} // namespace

TEST_CASE("linear layers pass the dot-product test in x and in the parameters") {
  dot_product_test(dpgen::Dense(7, 5), 5, 1);
  dot_product_test(dpgen::Conv1d(2, 3, 16, 3), 3, 11);
  dot_product_test(dpgen::Conv1d(1, 2, 9, 5), 2, 21);
  dot_product_test(dpgen::Conv2d(2, 3, 6, 5, 3), 3, 31);
  dot_product_test(dpgen::Conv2d(1, 1, 5, 5, 5), 1, 41);
}

TEST_CASE("activations' adjoints match central differences") {
  VectorXd x = random_vector(40, 51);
  activation_test(dpgen::Tanh(40), x, 52);
  // Keep ReLU inputs away from the kink, where central differences straddle it.
  for (Eigen::Index i = 0; i < x.size(); ++i)
    if (std::abs(x[i]) < 1e-3)
      x[i] = 0.5;
  activation_test(dpgen::Relu(40), x, 53);
}

TEST_CASE("periodic convolutions shift as their kernels say") {
  // A kernel that is a unit impulse at offset +1 reads the right neighbour, wrapping around.
  const dpgen::Conv1d conv1(1, 1, 6, 3);
  VectorXd p1 = VectorXd::Zero(conv1.parameter_count());
  p1[2] = 1.0;  // w[0][0][k = 2]: offset k - K/2 = +1
  p1[3] = 0.25; // bias
  const VectorXd x1 = VectorXd::LinSpaced(6, 0.0, 5.0);
  const VectorXd y1 = apply(conv1, p1, x1);
  for (int i = 0; i < 6; ++i)
    CHECK(y1[i] == x1[(i + 1) % 6] + 0.25);

  // 2D: impulse at (kj, ki) = (0, 2) reads x[j - 1][i + 1]; channel 1 of the output sums
  // both input channels at the centre.
  const int nx = 4, ny = 3;
  const dpgen::Conv2d conv2(2, 2, nx, ny, 3);
  VectorXd p2 = VectorXd::Zero(conv2.parameter_count());
  p2[((0 * 2 + 0) * 3 + 0) * 3 + 2] = 1.0; // co 0, ci 0, kj 0, ki 2
  p2[((1 * 2 + 0) * 3 + 1) * 3 + 1] = 1.0; // co 1, ci 0, centre
  p2[((1 * 2 + 1) * 3 + 1) * 3 + 1] = 1.0; // co 1, ci 1, centre
  const VectorXd x2 = random_vector(2 * nx * ny, 61);
  const VectorXd y2 = apply(conv2, p2, x2);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      CHECK(y2[j * nx + i] == x2[((j + ny - 1) % ny) * nx + (i + 1) % nx]);
      CHECK(y2[nx * ny + j * nx + i] == x2[j * nx + i] + x2[nx * ny + j * nx + i]);
    }

  const dpgen::Dense dense(3, 2);
  VectorXd pd(8);
  pd << 1, 2, 3, 4, 5, 6, 0.5, -0.5; // W = [1 3 5; 2 4 6] column-major, b = (0.5, -0.5)
  const VectorXd yd = apply(dense, pd, VectorXd::Ones(3));
  CHECK(yd[0] == 9.5);
  CHECK(yd[1] == 11.5);
}

TEST_CASE("network gradients match central differences") {
  dpgen::Sequential mlp;
  mlp.emplace<dpgen::Dense>(6, 10, dpgen::Init::he)
      .emplace<dpgen::Relu>(10)
      .emplace<dpgen::Dense>(10, 8)
      .emplace<dpgen::Tanh>(8)
      .emplace<dpgen::Dense>(8, 3);
  network_gradient_test(mlp, 3);

  // The correction network shape of a solver-in-the-loop setup: conv -> tanh -> conv.
  const int n = 16;
  dpgen::Sequential conv;
  conv.emplace<dpgen::Conv1d>(1, 4, n, 5)
      .emplace<dpgen::Tanh>(4 * n)
      .emplace<dpgen::Conv1d>(4, 1, n, 3);
  network_gradient_test(conv, 4);

  dpgen::Sequential conv2;
  conv2.emplace<dpgen::Conv2d>(2, 3, 6, 5, 3)
      .emplace<dpgen::Tanh>(90)
      .emplace<dpgen::Conv2d>(3, 2, 6, 5, 3);
  network_gradient_test(conv2, 5);
}

TEST_CASE("initialization is deterministic and scaled") {
  dpgen::Sequential net;
  net.emplace<dpgen::Dense>(200, 100).emplace<dpgen::Tanh>(100).emplace<dpgen::Dense>(
      100, 50, dpgen::Init::he);
  const VectorXd a = net.initialize(42), b = net.initialize(42), c = net.initialize(43);
  REQUIRE(a.size() == net.parameter_count());
  CHECK(std::memcmp(a.data(), b.data(), sizeof(double) * std::size_t(a.size())) == 0);
  CHECK((a - c).norm() > 0.0);

  // Dense(200, 100), Glorot: uniform on [-a, a], a = sqrt(6 / 300), variance a^2 / 3; biases 0.
  const double limit = std::sqrt(6.0 / 300.0);
  const auto w1 = a.head(20000);
  CHECK(w1.cwiseAbs().maxCoeff() <= limit);
  CHECK(w1.cwiseAbs().maxCoeff() > 0.99 * limit);
  const double variance = w1.squaredNorm() / 20000.0;
  CHECK(variance == doctest::Approx(limit * limit / 3.0).epsilon(0.05));
  CHECK(a.segment(20000, 100).isZero(0.0));
  // Dense(100, 50), He: a = sqrt(6 / 100).
  const auto w2 = a.segment(net.offset(2), 5000);
  CHECK(w2.cwiseAbs().maxCoeff() <= std::sqrt(0.06));
  CHECK(w2.cwiseAbs().maxCoeff() > 0.99 * std::sqrt(0.06));
}

TEST_CASE("an optimizer trains the flat parameter vector") {
  // Learn the periodic 3-point smoother y[i] = (x[i-1] + 2 x[i] + x[i+1]) / 4 from samples.
  const int n = 12, samples = 8;
  dpgen::Sequential net;
  net.emplace<dpgen::Conv1d>(1, 2, n, 3)
      .emplace<dpgen::Tanh>(2 * n)
      .emplace<dpgen::Conv1d>(2, 1, n, 3);
  std::vector<VectorXd> xs, ys;
  for (int s = 0; s < samples; ++s) {
    xs.push_back(0.5 * random_vector(n, 100 + s));
    VectorXd y(n);
    for (int i = 0; i < n; ++i)
      y[i] = (xs[s][(i + n - 1) % n] + 2 * xs[s][i] + xs[s][(i + 1) % n]) / 4;
    ys.push_back(y);
  }
  const dpgen::LossGradient f = [&](const VectorXd& p, VectorXd& grad) {
    grad.setZero(p.size());
    double total = 0.0;
    dpgen::Sequential::Activations acts;
    VectorXd x_adj;
    for (int s = 0; s < samples; ++s) {
      net.forward(p, xs[s], acts);
      const VectorXd r = acts.output() - ys[s];
      total += 0.5 * r.squaredNorm();
      x_adj.resize(0);
      net.backward(p, acts, r, x_adj, grad);
    }
    return total;
  };
  VectorXd p = net.initialize(7);
  VectorXd g;
  const double initial = f(p, g);
  dpgen::Adam adam(dpgen::AdamOptions{0.02, 0.9, 0.999, 1e-8});
  dpgen::TrainOptions options;
  options.max_iterations = 300;
  const dpgen::TrainSummary summary = dpgen::train(f, adam, p, options);
  CHECK(summary.final_loss < 1e-2 * initial);
}

TEST_CASE("network errors") {
  dpgen::Sequential net;
  net.emplace<dpgen::Dense>(4, 32).emplace<dpgen::Tanh>(32);
  CHECK_THROWS_WITH_AS(net.emplace<dpgen::Dense>(16, 8),
                       "Sequential: layer 2 (Dense(16 -> 8)) takes 16 inputs but layer 1 "
                       "(Tanh(32)) gives 32",
                       std::invalid_argument);
  const VectorXd p = net.initialize(1);
  CHECK_THROWS_WITH_AS(net(VectorXd::Zero(3), VectorXd::Zero(4)),
                       "Sequential forward: parameter vector has size 3, expected 160",
                       std::invalid_argument);
  CHECK_THROWS_WITH_AS(net(p, VectorXd::Zero(5)),
                       "Sequential forward: input has size 5, expected 4", std::invalid_argument);
  dpgen::Sequential::Activations acts;
  VectorXd x_adj, p_adj;
  CHECK_THROWS_WITH_AS(net.backward(p, acts, VectorXd::Zero(32), x_adj, p_adj),
                       "Sequential backward: activations hold 0 values, expected 3 (run forward "
                       "first)",
                       std::invalid_argument);
  net.forward(p, VectorXd::Zero(4), acts);
  CHECK_THROWS_WITH_AS(net.backward(p, acts, VectorXd::Zero(31), x_adj, p_adj),
                       "Sequential backward: output adjoint has size 31, expected 32",
                       std::invalid_argument);
  CHECK_THROWS_AS(dpgen::Conv1d(1, 1, 8, 4), std::invalid_argument);    // even kernel
  CHECK_THROWS_AS(dpgen::Conv2d(1, 1, 4, 2, 3), std::invalid_argument); // kernel wider than ny
}
