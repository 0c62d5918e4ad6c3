// Small network layers for solver-in-the-loop training: dense, periodic 1D/2D convolution,
// tanh and ReLU, with adjoints; all parameters live in one flat vector the optimizers update.
#pragma once

#include "dpgen/error.hpp"

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace dpgen {

/// A read-only view of a vector or of a contiguous slice of one.
using ConstVectorRef = Eigen::Ref<const Eigen::VectorXd>;
/// A writable view of a vector or of a contiguous slice of one.
using VectorRef = Eigen::Ref<Eigen::VectorXd>;

/// Initial weight scale: uniform on [-a, a] with a = sqrt(6 / (fan_in + fan_out)) (Glorot,
/// for tanh) or a = sqrt(6 / fan_in) (He, for ReLU). Biases start at zero.
enum class Init { glorot, he };

namespace detail {

// Uniform on [-a, a) from the generator's raw 64-bit output: the same numbers on every
// platform (std::uniform_real_distribution is implementation-defined).
inline double uniform_symmetric(std::mt19937_64& rng, double a) {
  const double u = static_cast<double>(rng() >> 11) * 0x1.0p-53; // [0, 1), 53 random bits
  return a * (2.0 * u - 1.0);
}

inline void initialize_weights(VectorRef weights, std::mt19937_64& rng, Init init, double fan_in,
                               double fan_out) {
  const double a =
      init == Init::glorot ? std::sqrt(6.0 / (fan_in + fan_out)) : std::sqrt(6.0 / fan_in);
  for (Eigen::Index i = 0; i < weights.size(); ++i)
    weights[i] = uniform_symmetric(rng, a);
}

inline int wrap(int i, int n) { return ((i % n) + n) % n; }

} // namespace detail

/// One layer y = layer(x; p). Layers hold only their shape; the parameters p are a slice of
/// the network's flat parameter vector, passed in.
class Layer {
public:
  virtual ~Layer() = default;
  /// Number of input values.
  virtual Eigen::Index input_size() const = 0;
  /// Number of output values.
  virtual Eigen::Index output_size() const = 0;
  /// Number of parameters (weights, then biases).
  virtual Eigen::Index parameter_count() const { return 0; }
  /// Draws initial parameters into `params` (size parameter_count()) from `rng`.
  virtual void initialize(VectorRef params, std::mt19937_64& rng) const {
    (void)params;
    (void)rng;
  }
  /// y = layer(x; params); y has output_size() entries.
  virtual void forward(ConstVectorRef params, ConstVectorRef x, VectorRef y) const = 0;
  /// The adjoint, given the forward's x and y: ADDS (dy/dx)^T y_adj into x_adj and
  /// (dy/dparams)^T y_adj into params_adj.
  virtual void backward(ConstVectorRef params, ConstVectorRef x, ConstVectorRef y,
                        ConstVectorRef y_adj, VectorRef x_adj, VectorRef params_adj) const = 0;
  /// A short description for messages, e.g. "Dense(16 -> 8)".
  virtual std::string describe() const = 0;
};

/// Fully connected layer y = W x + b, W out-by-in (column-major in the parameter slice,
/// followed by b).
class Dense : public Layer {
public:
  Dense(Eigen::Index inputs, Eigen::Index outputs, Init init = Init::glorot)
      : in_(inputs), out_(outputs), init_(init) {
    if (inputs < 1 || outputs < 1)
      throw std::invalid_argument(
          detail::message("Dense: sizes must be positive (got ", inputs, " -> ", outputs, ")"));
  }
  Eigen::Index input_size() const override { return in_; }
  Eigen::Index output_size() const override { return out_; }
  Eigen::Index parameter_count() const override { return out_ * in_ + out_; }
  void initialize(VectorRef params, std::mt19937_64& rng) const override {
    detail::initialize_weights(params.head(out_ * in_), rng, init_, double(in_), double(out_));
    params.tail(out_).setZero();
  }
  void forward(ConstVectorRef params, ConstVectorRef x, VectorRef y) const override {
    y.noalias() = weights(params) * x; // y = W x + b
    y += params.tail(out_);
  }
  void backward(ConstVectorRef params, ConstVectorRef x, ConstVectorRef, ConstVectorRef y_adj,
                VectorRef x_adj, VectorRef params_adj) const override {
    x_adj.noalias() += weights(params).transpose() * y_adj; // x_adj += W^T y_adj
    Eigen::Map<Eigen::MatrixXd> w_adj(params_adj.data(), out_, in_);
    w_adj.noalias() += y_adj * x.transpose(); // W_adj += y_adj x^T
    params_adj.tail(out_) += y_adj;           // b_adj += y_adj
  }
  std::string describe() const override {
    return detail::message("Dense(", in_, " -> ", out_, ")");
  }

private:
  Eigen::Map<const Eigen::MatrixXd> weights(ConstVectorRef params) const {
    return Eigen::Map<const Eigen::MatrixXd>(params.data(), out_, in_);
  }
  Eigen::Index in_, out_;
  Init init_;
};

/// 1D convolution with periodic padding on n cells, channel-major layout (x[c * n + i]):
///   y[co][i] = b[co] + sum_ci sum_k w[co][ci][k] x[ci][(i + k - K/2) mod n],
/// K odd, weights w[(co * cin + ci) * K + k] followed by the biases.
class Conv1d : public Layer {
public:
  Conv1d(int channels_in, int channels_out, int n, int kernel_size, Init init = Init::glorot)
      : cin_(channels_in), cout_(channels_out), n_(n), k_(kernel_size), init_(init) {
    if (channels_in < 1 || channels_out < 1 || n < 1 || kernel_size < 1 || kernel_size % 2 == 0 ||
        kernel_size > n)
      throw std::invalid_argument(detail::message(
          "Conv1d: need positive channels and cells and an odd kernel size <= n (got ", channels_in,
          " -> ", channels_out, " channels, n ", n, ", kernel ", kernel_size, ")"));
  }
  Eigen::Index input_size() const override { return Eigen::Index(cin_) * n_; }
  Eigen::Index output_size() const override { return Eigen::Index(cout_) * n_; }
  Eigen::Index parameter_count() const override { return Eigen::Index(cout_) * cin_ * k_ + cout_; }
  void initialize(VectorRef params, std::mt19937_64& rng) const override {
    const Eigen::Index nw = Eigen::Index(cout_) * cin_ * k_;
    detail::initialize_weights(params.head(nw), rng, init_, double(cin_ * k_), double(cout_ * k_));
    params.tail(cout_).setZero();
  }
  void forward(ConstVectorRef params, ConstVectorRef x, VectorRef y) const override {
    const int r = k_ / 2;
    for (int co = 0; co < cout_; ++co)
      for (int i = 0; i < n_; ++i) {
        double sum = params[bias(co)];
        for (int ci = 0; ci < cin_; ++ci)
          for (int k = 0; k < k_; ++k)
            sum += params[weight(co, ci, k)] * x[ci * n_ + detail::wrap(i + k - r, n_)];
        y[co * n_ + i] = sum;
      }
  }
  void backward(ConstVectorRef params, ConstVectorRef x, ConstVectorRef, ConstVectorRef y_adj,
                VectorRef x_adj, VectorRef params_adj) const override {
    const int r = k_ / 2;
    for (int co = 0; co < cout_; ++co)
      for (int i = 0; i < n_; ++i) {
        const double g = y_adj[co * n_ + i];
        params_adj[bias(co)] += g; // b_adj[co] += sum_i y_adj[co][i]
        for (int ci = 0; ci < cin_; ++ci)
          for (int k = 0; k < k_; ++k) {
            const int j = ci * n_ + detail::wrap(i + k - r, n_);
            params_adj[weight(co, ci, k)] += g * x[j]; // w_adj += y_adj x(shifted)
            x_adj[j] += params[weight(co, ci, k)] * g; // x_adj(shifted) += w y_adj
          }
      }
  }
  std::string describe() const override {
    return detail::message("Conv1d(", cin_, " -> ", cout_, " channels, n ", n_, ", kernel ", k_,
                           ")");
  }

private:
  Eigen::Index weight(int co, int ci, int k) const {
    return (Eigen::Index(co) * cin_ + ci) * k_ + k;
  }
  Eigen::Index bias(int co) const { return Eigen::Index(cout_) * cin_ * k_ + co; }
  int cin_, cout_, n_, k_;
  Init init_;
};

/// 2D convolution with periodic padding on an nx-by-ny grid, layout x[(c * ny + j) * nx + i]
/// (row-major per channel, as the stencil kernels index k = j * nx + i):
///   y[co][j][i] = b[co] + sum_ci sum_kj,ki w[co][ci][kj][ki] x[ci][(j+kj-K/2) mod ny][(i+ki-K/2)
///   mod nx],
/// K odd, weights w[((co * cin + ci) * K + kj) * K + ki] followed by the biases.
class Conv2d : public Layer {
public:
  Conv2d(int channels_in, int channels_out, int nx, int ny, int kernel_size,
         Init init = Init::glorot)
      : cin_(channels_in), cout_(channels_out), nx_(nx), ny_(ny), k_(kernel_size), init_(init) {
    if (channels_in < 1 || channels_out < 1 || nx < 1 || ny < 1 || kernel_size < 1 ||
        kernel_size % 2 == 0 || kernel_size > nx || kernel_size > ny)
      throw std::invalid_argument(detail::message(
          "Conv2d: need positive channels and grid sizes and an odd kernel size <= nx, ny (got ",
          channels_in, " -> ", channels_out, " channels, ", nx, " x ", ny, ", kernel ", kernel_size,
          ")"));
  }
  Eigen::Index input_size() const override { return Eigen::Index(cin_) * nx_ * ny_; }
  Eigen::Index output_size() const override { return Eigen::Index(cout_) * nx_ * ny_; }
  Eigen::Index parameter_count() const override {
    return Eigen::Index(cout_) * cin_ * k_ * k_ + cout_;
  }
  void initialize(VectorRef params, std::mt19937_64& rng) const override {
    const Eigen::Index nw = Eigen::Index(cout_) * cin_ * k_ * k_;
    detail::initialize_weights(params.head(nw), rng, init_, double(cin_ * k_ * k_),
                               double(cout_ * k_ * k_));
    params.tail(cout_).setZero();
  }
  void forward(ConstVectorRef params, ConstVectorRef x, VectorRef y) const override {
    const int r = k_ / 2;
    for (int co = 0; co < cout_; ++co)
      for (int j = 0; j < ny_; ++j)
        for (int i = 0; i < nx_; ++i) {
          double sum = params[bias(co)];
          for (int ci = 0; ci < cin_; ++ci)
            for (int kj = 0; kj < k_; ++kj)
              for (int ki = 0; ki < k_; ++ki)
                sum += params[weight(co, ci, kj, ki)] * x[cell(ci, j + kj - r, i + ki - r)];
          y[cell(co, j, i)] = sum;
        }
  }
  void backward(ConstVectorRef params, ConstVectorRef x, ConstVectorRef, ConstVectorRef y_adj,
                VectorRef x_adj, VectorRef params_adj) const override {
    const int r = k_ / 2;
    for (int co = 0; co < cout_; ++co)
      for (int j = 0; j < ny_; ++j)
        for (int i = 0; i < nx_; ++i) {
          const double g = y_adj[cell(co, j, i)];
          params_adj[bias(co)] += g;
          for (int ci = 0; ci < cin_; ++ci)
            for (int kj = 0; kj < k_; ++kj)
              for (int ki = 0; ki < k_; ++ki) {
                const Eigen::Index s = cell(ci, j + kj - r, i + ki - r);
                const Eigen::Index w = weight(co, ci, kj, ki);
                params_adj[w] += g * x[s];
                x_adj[s] += params[w] * g;
              }
        }
  }
  std::string describe() const override {
    return detail::message("Conv2d(", cin_, " -> ", cout_, " channels, ", nx_, " x ", ny_,
                           ", kernel ", k_, ")");
  }

private:
  // Index of cell (j, i) of channel c, with periodic wrap.
  Eigen::Index cell(int c, int j, int i) const {
    return (Eigen::Index(c) * ny_ + detail::wrap(j, ny_)) * nx_ + detail::wrap(i, nx_);
  }
  Eigen::Index weight(int co, int ci, int kj, int ki) const {
    return ((Eigen::Index(co) * cin_ + ci) * k_ + kj) * k_ + ki;
  }
  Eigen::Index bias(int co) const { return Eigen::Index(cout_) * cin_ * k_ * k_ + co; }
  int cin_, cout_, nx_, ny_, k_;
  Init init_;
};

/// Elementwise y = tanh(x); adjoint x_adj += (1 - y^2) y_adj.
class Tanh : public Layer {
public:
  explicit Tanh(Eigen::Index n) : n_(n) {}
  Eigen::Index input_size() const override { return n_; }
  Eigen::Index output_size() const override { return n_; }
  void forward(ConstVectorRef, ConstVectorRef x, VectorRef y) const override {
    y = x.array().tanh().matrix();
  }
  void backward(ConstVectorRef, ConstVectorRef, ConstVectorRef y, ConstVectorRef y_adj,
                VectorRef x_adj, VectorRef) const override {
    x_adj.array() += (1.0 - y.array().square()) * y_adj.array();
  }
  std::string describe() const override { return detail::message("Tanh(", n_, ")"); }

private:
  Eigen::Index n_;
};

/// Elementwise y = max(x, 0); adjoint x_adj += [x > 0] y_adj (derivative 0 at x = 0).
class Relu : public Layer {
public:
  explicit Relu(Eigen::Index n) : n_(n) {}
  Eigen::Index input_size() const override { return n_; }
  Eigen::Index output_size() const override { return n_; }
  void forward(ConstVectorRef, ConstVectorRef x, VectorRef y) const override {
    y = x.cwiseMax(0.0);
  }
  void backward(ConstVectorRef, ConstVectorRef x, ConstVectorRef, ConstVectorRef y_adj,
                VectorRef x_adj, VectorRef) const override {
    x_adj.array() += (x.array() > 0.0).cast<double>() * y_adj.array();
  }
  std::string describe() const override { return detail::message("Relu(", n_, ")"); }

private:
  Eigen::Index n_;
};

/// A chain of layers with one flat parameter vector: layer l owns the slice
/// [offset(l), offset(l) + layer(l).parameter_count()). Layers are immutable and shared, so
/// copies of a Sequential are cheap.
class Sequential {
public:
  /// The values a forward pass keeps for the backward pass: values[0] is the input,
  /// values[l + 1] the output of layer l.
  struct Activations {
    std::vector<Eigen::VectorXd> values;
    /// The network's output.
    const Eigen::VectorXd& output() const { return values.back(); }
  };

  /// Appends a layer; its input size must equal the previous layer's output size.
  Sequential& add(std::shared_ptr<const Layer> layer) {
    if (!layer)
      throw std::invalid_argument("Sequential: null layer");
    if (!layers_.empty() && layer->input_size() != layers_.back()->output_size())
      throw std::invalid_argument(
          detail::message("Sequential: layer ", layers_.size(), " (", layer->describe(), ") takes ",
                          layer->input_size(), " inputs but layer ", layers_.size() - 1, " (",
                          layers_.back()->describe(), ") gives ", layers_.back()->output_size()));
    offsets_.push_back(parameter_count());
    layers_.push_back(std::move(layer));
    return *this;
  }
  /// Constructs a layer in place: `net.emplace<Dense>(16, 8)`.
  template <typename L, typename... Args> Sequential& emplace(Args&&... args) {
    return add(std::make_shared<const L>(std::forward<Args>(args)...));
  }

  /// Number of layers.
  std::size_t size() const { return layers_.size(); }
  /// Layer l.
  const Layer& layer(std::size_t l) const { return *layers_.at(l); }
  /// Start of layer l's slice in the parameter vector.
  Eigen::Index offset(std::size_t l) const { return offsets_.at(l); }
  /// Input size of the first layer (0 when empty).
  Eigen::Index input_size() const { return layers_.empty() ? 0 : layers_.front()->input_size(); }
  /// Output size of the last layer (0 when empty).
  Eigen::Index output_size() const { return layers_.empty() ? 0 : layers_.back()->output_size(); }
  /// Total number of parameters.
  Eigen::Index parameter_count() const {
    return layers_.empty() ? 0 : offsets_.back() + layers_.back()->parameter_count();
  }

  /// Fresh parameters: one std::mt19937_64 seeded with `seed`, drawn layer by layer. The same
  /// seed gives the same vector, bit for bit, on every platform.
  Eigen::VectorXd initialize(std::uint64_t seed) const {
    std::mt19937_64 rng(seed);
    Eigen::VectorXd params = Eigen::VectorXd::Zero(parameter_count());
    for (std::size_t l = 0; l < layers_.size(); ++l)
      layers_[l]->initialize(slice(params, l), rng);
    return params;
  }

  /// Forward pass keeping every layer's output in `acts` (reused across calls).
  void forward(const Eigen::VectorXd& params, const Eigen::VectorXd& x, Activations& acts) const {
    check_sizes(params, x.size(), "forward", "input");
    acts.values.resize(layers_.size() + 1);
    acts.values[0] = x;
    for (std::size_t l = 0; l < layers_.size(); ++l) {
      acts.values[l + 1].resize(layers_[l]->output_size());
      layers_[l]->forward(slice(params, l), acts.values[l], acts.values[l + 1]);
    }
  }
  /// Forward pass returning only the output.
  Eigen::VectorXd operator()(const Eigen::VectorXd& params, const Eigen::VectorXd& x) const {
    Activations acts;
    forward(params, x, acts);
    return acts.values.back();
  }

  /// Backward pass through the activations of forward(params, x, acts): ADDS (dy/dx)^T y_adj
  /// into x_adj and (dy/dparams)^T y_adj into params_adj. Empty x_adj or params_adj are first
  /// resized to zeros.
  void backward(const Eigen::VectorXd& params, const Activations& acts,
                const Eigen::VectorXd& y_adj, Eigen::VectorXd& x_adj,
                Eigen::VectorXd& params_adj) const {
    const char* where = "Sequential backward";
    if (acts.values.size() != layers_.size() + 1)
      throw std::invalid_argument(detail::message(where, ": activations hold ", acts.values.size(),
                                                  " values, expected ", layers_.size() + 1,
                                                  " (run forward first)"));
    check_sizes(params, acts.values[0].size(), "backward", "input");
    detail::require_size(y_adj.size(), output_size(), where, "output adjoint");
    if (x_adj.size() == 0)
      x_adj.setZero(input_size());
    if (params_adj.size() == 0)
      params_adj.setZero(parameter_count());
    detail::require_size(x_adj.size(), input_size(), where, "input adjoint");
    detail::require_size(params_adj.size(), parameter_count(), where, "parameter adjoint");
    Eigen::VectorXd g = y_adj, g_in;
    for (std::size_t l = layers_.size(); l-- > 0;) {
      g_in.setZero(layers_[l]->input_size());
      layers_[l]->backward(slice(params, l), acts.values[l], acts.values[l + 1], g, g_in,
                           slice(params_adj, l));
      g.swap(g_in);
    }
    x_adj += g;
  }

private:
  Eigen::VectorBlock<const Eigen::VectorXd> slice(const Eigen::VectorXd& v, std::size_t l) const {
    return v.segment(offsets_[l], layers_[l]->parameter_count());
  }
  Eigen::VectorBlock<Eigen::VectorXd> slice(Eigen::VectorXd& v, std::size_t l) const {
    return v.segment(offsets_[l], layers_[l]->parameter_count());
  }
  void check_sizes(const Eigen::VectorXd& params, Eigen::Index x_size, const char* pass,
                   const char* what) const {
    if (layers_.empty())
      throw std::invalid_argument(detail::message("Sequential ", pass, ": no layers"));
    const std::string where = detail::message("Sequential ", pass);
    detail::require_size(params.size(), parameter_count(), where, "parameter vector");
    detail::require_size(x_size, input_size(), where, what);
  }

  std::vector<std::shared_ptr<const Layer>> layers_;
  std::vector<Eigen::Index> offsets_;
};

} // namespace dpgen
