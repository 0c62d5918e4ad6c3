// Tests of the examples' training log (examples/common/csv_log.hpp), fed by dpgen::train()'s
// observer: header and rows, the .partial file while running, publication by rename when the
// run ends (also by an exception), replacement of an older log, and write errors.
#include "csv_log.hpp"

#include <doctest/doctest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace {

using Eigen::VectorXd;
namespace fs = std::filesystem;

// f(x) = 1/2 sum_i (i + 1) (x_i - 1)^2: minimum 0 at x = 1.
double bowl(const VectorXd& x, VectorXd& grad) {
  const VectorXd w = VectorXd::LinSpaced(x.size(), 1.0, double(x.size()));
  grad = w.cwiseProduct(x - VectorXd::Ones(x.size()));
  return 0.5 * w.dot((x - VectorXd::Ones(x.size())).cwiseAbs2());
}

// A fresh, empty directory for this test binary's logs.
fs::path scratch_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("dpgen_csv_log_test_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::vector<std::string> read_lines(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  for (std::string field; std::getline(in, field, ',');)
    fields.push_back(field);
  return fields;
}

} // namespace

TEST_CASE("csv log: header, one row per iteration from the observer, published at the end") {
  const fs::path dir = scratch_dir("rows");
  const fs::path csv = dir / "log.csv";
  std::vector<dpgen::TrainProgress> rows;
  dpgen::TrainOptions options;
  options.max_iterations = 5;
  options.callback = [&](const dpgen::TrainProgress& p) {
    rows.push_back(p);
    // During the run only the .partial file exists, already holding every row so far.
    CHECK_FALSE(fs::exists(csv));
    CHECK(read_lines(csv.string() + ".partial").size() == rows.size() + 1);
  };
  const auto log = dpgen_examples::attach_csv_log(options, csv.string());
  dpgen::GradientDescent gd({0.1});
  VectorXd x = VectorXd::Zero(4);
  dpgen::train(bowl, gd, x, options);
  REQUIRE(rows.size() == 6);
  CHECK(fs::exists(csv.string() + ".partial")); // not published before close()
  log->close();

  CHECK_FALSE(fs::exists(csv.string() + ".partial"));
  const std::vector<std::string> lines = read_lines(csv);
  REQUIRE(lines.size() == 7);
  CHECK(lines[0] == "iter,loss,grad_norm,seconds");
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const std::vector<std::string> fields = split(lines[i + 1]);
    REQUIRE(fields.size() == 4);
    CHECK(std::stoi(fields[0]) == static_cast<int>(i));
    CHECK(std::strtod(fields[1].c_str(), nullptr) == rows[i].loss); // %.17g round-trips
    CHECK(std::strtod(fields[2].c_str(), nullptr) == rows[i].grad_norm);
    CHECK(std::strtod(fields[3].c_str(), nullptr) >= 0.0);
  }

  // A second run replaces the log; a temporary TrainOptions publishes it when train() returns.
  {
    dpgen::TrainOptions second;
    second.max_iterations = 2;
    dpgen_examples::attach_csv_log(second, csv.string());
    VectorXd y = VectorXd::Zero(4);
    dpgen::train(bowl, gd, y, second);
  }
  CHECK(read_lines(csv).size() == 4);
  CHECK_FALSE(fs::exists(csv.string() + ".partial"));
  fs::remove_all(dir);
}

TEST_CASE("csv log: a run stopped by NaN leaves the complete log, ending with its row") {
  const fs::path dir = scratch_dir("nan");
  const fs::path csv = dir / "log.csv";
  int evaluations = 0;
  const dpgen::LossGradient poisoned = [&](const VectorXd& x, VectorXd& grad) {
    const double loss = bowl(x, grad);
    return ++evaluations == 8 ? std::numeric_limits<double>::quiet_NaN() : loss;
  };
  dpgen::GradientDescent gd({0.1});
  VectorXd x = VectorXd::Zero(3);
  try {
    dpgen::TrainOptions options;
    options.max_iterations = 50;
    dpgen_examples::attach_csv_log(options, csv.string());
    dpgen::train(poisoned, gd, x, options);
    FAIL("expected a TrainingError");
  } catch (const dpgen::TrainingError& e) {
    CHECK(e.iteration() == 7);
  }
  CHECK_FALSE(fs::exists(csv.string() + ".partial"));
  const std::vector<std::string> lines = read_lines(csv);
  REQUIRE(lines.size() == 9);
  CHECK(lines.back().rfind("7,nan,", 0) == 0);
  fs::remove_all(dir);
}

TEST_CASE("csv log: an empty path logs nothing; an unwritable one throws") {
  dpgen::TrainOptions options;
  const auto none = dpgen_examples::attach_csv_log(options, "");
  CHECK_FALSE(options.callback); // nothing hooked in
  none->close();
  CHECK_THROWS_WITH_AS(dpgen_examples::CsvLog("/nonexistent-dir/log.csv"),
                       "csv log: cannot open '/nonexistent-dir/log.csv.partial' for writing",
                       std::runtime_error);
}

TEST_CASE("csv log: a header of the caller's and rows as text (the examples' other CSVs)") {
  const fs::path dir = scratch_dir("lines");
  const fs::path csv = dir / "iterates.csv";
  {
    dpgen_examples::CsvLog log(csv.string(), "method,iter,loss");
    log.line("GD,0," + dpgen_examples::number(0.1));
    CHECK_FALSE(fs::exists(csv)); // still <path>.partial while it is written
    CHECK(fs::exists(csv.string() + ".partial"));
    log.line("GD,1," + dpgen_examples::number(1.0 / 3.0));
    log.close();
  }
  const std::vector<std::string> lines = read_lines(csv);
  REQUIRE(lines.size() == 3);
  CHECK(lines[0] == "method,iter,loss");
  CHECK(lines[1] == "GD,0,0.10000000000000001");
  // number() round-trips: the field reads back to the same double.
  CHECK(std::stod(split(lines[2])[2]) == 1.0 / 3.0);
  fs::remove_all(dir);
}
