// Tests of the examples' command-line parser (examples/common/cli.hpp): defaults come back
// exactly as written in the code (not through six-digit text), given values are parsed, and
// malformed, out-of-range or unknown options are errors that name the value.
#include "cli.hpp"

#include <doctest/doctest.h>

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

using dpgen_examples::Args;

// Args from a command line (the program name first).
Args parse(std::vector<std::string> words) {
  words.insert(words.begin(), "prog");
  std::vector<char*> argv;
  for (auto& w : words)
    argv.push_back(w.data());
  return Args(int(argv.size()), argv.data(), "prog", "a test program");
}

std::string finish_error(Args& args) {
  try {
    args.finish();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

} // namespace

TEST_CASE("defaults round-trip exactly") {
  const double third = 1.0 / 3.0, nu = 0.01 / M_PI, tiny = 1e-300, big = 1.0 / 7.0 * 1e10;
  Args args = parse({});
  CHECK(args.get_double("--third", third, "") == third);
  CHECK(args.get_double("--nu", nu, "", 0, 1, true) == nu);
  CHECK(args.get_double("--tiny", tiny, "", 0) == tiny);
  CHECK(args.get_double("--big", big, "") == big);
  CHECK(args.get_int("--n", 2147483647, "") == 2147483647);
  CHECK(args.get_string("--s", "text", "") == "text");
  CHECK_FALSE(args.finish());
}

TEST_CASE("--help shows each default as text that reads back as it") {
  for (const double v : {1.0 / 3.0, 0.01 / M_PI, 0.1, 1e-3, 2.0 / 3.0 * 1e-7, 5.0, -0.0})
    CHECK(std::strtod(Args::format(v).c_str(), nullptr) == v);
  CHECK(Args::format(0.1) == "0.1"); // the shortest such text
  CHECK(Args::format(1e-3) == "0.001");
  CHECK(Args::format(5.0) == "5");
}

TEST_CASE("given values are parsed; --name=value too") {
  Args args = parse({"--x", "0.25", "--n=7", "--s", "abc"});
  CHECK(args.get_double("--x", 1.0 / 3.0, "") == 0.25);
  CHECK(args.get_int("--n", 1, "") == 7);
  CHECK(args.get_string("--s", "", "") == "abc");
  CHECK_FALSE(args.finish());
}

TEST_CASE("bad values and unknown options are errors naming them") {
  {
    Args args = parse({"--x", "abc"});
    args.get_double("--x", 1.0, "");
    CHECK(finish_error(args) == "prog: --x expects a finite number, got 'abc'");
  }
  {
    Args args = parse({"--x", "-1"});
    args.get_double("--x", 1.0, "", 0, 1, true);
    CHECK(finish_error(args) == "prog: --x must be from 0 to 1, got -1");
  }
  {
    Args args = parse({"--n", "1.5"});
    args.get_int("--n", 1, "");
    CHECK(finish_error(args) == "prog: --n expects an integer, got '1.5'");
  }
  {
    Args args = parse({"--y", "1"});
    args.get_double("--x", 1.0, "");
    CHECK(finish_error(args) == "prog: unknown option --y (see --help)");
  }
}
