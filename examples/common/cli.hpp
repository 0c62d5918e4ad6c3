// A small command-line parser for the examples: --name value options with
// defaults and ranges, --help naming both, and a clear error, with the value
// given, for anything unknown, malformed or out of range.
#pragma once

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace dpgen_examples {

class Args {
public:
  Args(int argc, char** argv, std::string program, std::string about)
      : program_(std::move(program)), about_(std::move(about)) {
    for (int i = 1; i < argc; ++i) {
      std::string a = argv[i];
      if (a == "--help" || a == "-h") {
        help_ = true;
        continue;
      }
      if (a.rfind("--", 0) != 0)
        throw std::invalid_argument(program_ + ": unexpected argument '" + a + "'");
      auto eq = a.find('=');
      if (eq != std::string::npos) {
        given_[a.substr(0, eq)] = a.substr(eq + 1);
      } else {
        if (i + 1 >= argc)
          throw std::invalid_argument(program_ + ": option " + a + " needs a value");
        given_[a] = argv[++i];
      }
    }
  }

  /// An integer option in [min, max]. A malformed or out-of-range value is
  /// reported by finish(), with the value given.
  int get_int(const std::string& name, int def, const std::string& help,
              int min = std::numeric_limits<int>::min(),
              int max = std::numeric_limits<int>::max()) {
    const std::string* given = get(name, std::to_string(def), help, range_text(min, max, false));
    if (!given)
      return def;
    const std::string& v = *given;
    char* end = nullptr;
    errno = 0;
    const long r = std::strtol(v.c_str(), &end, 10);
    if (v.empty() || *end) {
      error(name + " expects an integer, got '" + v + "'");
      return def;
    }
    if (errno == ERANGE || r < min || r > max) {
      error(name + " must be " + range_text(min, max, false) + ", got " + v);
      return def;
    }
    return static_cast<int>(r);
  }

  /// A finite number in [min, max] (min excluded if min_excluded).
  double get_double(const std::string& name, double def, const std::string& help,
                    double min = -std::numeric_limits<double>::infinity(),
                    double max = std::numeric_limits<double>::infinity(),
                    bool min_excluded = false) {
    const std::string* given = get(name, format(def), help, range_text(min, max, min_excluded));
    if (!given)
      return def; // the default itself: text would round it (1/3, 0.01/pi)
    const std::string& v = *given;
    char* end = nullptr;
    const double r = std::strtod(v.c_str(), &end);
    if (v.empty() || *end || !std::isfinite(r)) {
      error(name + " expects a finite number, got '" + v + "'");
      return def;
    }
    if (r < min || r > max || (min_excluded && r == min)) {
      error(name + " must be " + range_text(min, max, min_excluded) + ", got " + v);
      return def;
    }
    return r;
  }

  std::string get_string(const std::string& name, const std::string& def, const std::string& help) {
    const std::string* given = get(name, def, help, "");
    return given ? *given : def;
  }

  /// Call after every get_*: prints help (returns true), or throws the first
  /// error of a value or an unknown option.
  bool finish() {
    if (help_) {
      std::printf("%s\n\nusage: %s [options]\n\n", about_.c_str(), program_.c_str());
      for (const auto& l : usage_)
        std::printf("%s\n", l.c_str());
      return true;
    }
    if (!errors_.empty())
      throw std::invalid_argument(errors_.front());
    for (const auto& [k, v] : given_)
      if (!known_.count(k))
        throw std::invalid_argument(program_ + ": unknown option " + k + " (see --help)");
    return false;
  }

  /// The shortest text (%.{6..17}g) that reads back as exactly v: what --help shows.
  static std::string format(double v) {
    char buf[64];
    for (int digits = 6; digits <= 17; ++digits) {
      std::snprintf(buf, sizeof buf, "%.*g", digits, v);
      if (std::strtod(buf, nullptr) == v)
        break;
    }
    return buf;
  }

  /// For a condition between options, after finish(): throws "<program>: <what>".
  [[noreturn]] void fail(const std::string& what) const {
    throw std::invalid_argument(program_ + ": " + what);
  }

private:
  // Registers the option for --help; the value given on the command line, or null (then the
  // caller returns its default as it is: never through text).
  const std::string* get(const std::string& name, const std::string& def, const std::string& help,
                         const std::string& range) {
    known_[name] = true;
    usage_.push_back("  " + name + " (default " + (def.empty() ? "none" : def) +
                     (range.empty() ? "" : "; " + range) + ")\n      " + help);
    auto it = given_.find(name);
    return it == given_.end() ? nullptr : &it->second;
  }
  void error(const std::string& what) { errors_.push_back(program_ + ": " + what); }
  template <typename T> static std::string range_text(T min, T max, bool min_excluded) {
    const bool has_min = min > std::numeric_limits<T>::lowest();
    const bool has_max = max < std::numeric_limits<T>::max();
    if (has_min && has_max)
      return "from " + format(min) + " to " + format(max);
    if (has_min)
      return (min_excluded ? "greater than " : "at least ") + format(min);
    if (has_max)
      return "at most " + format(max);
    return "";
  }
  std::string program_, about_;
  std::map<std::string, std::string> given_;
  std::map<std::string, bool> known_;
  std::vector<std::string> usage_, errors_;
  bool help_ = false;
};

/// The options every example has besides its own.
struct CommonOptions {
  std::string csv;    ///< --csv: the training log
  std::string out;    ///< --out: folder for pictures
  double require = 0; ///< --require-reduction: fail below this loss ratio
  bool check = false; ///< --check-gradient: compare with central differences and exit
};

/// `csv_log` false: no --csv option (examples that write their CSVs into --out).
inline CommonOptions common_options(Args& args, const std::string& name, bool csv_log = true) {
  CommonOptions o;
  if (csv_log)
    o.csv = args.get_string("--csv", "", "CSV log path (iter,loss,grad_norm,seconds); none: no log");
  o.out = args.get_string("--out", "out/" + name, "folder for pictures");
  o.require = args.get_double("--require-reduction", 0,
                              "exit with an error unless the loss drops by this factor (0: "
                              "no requirement)",
                              0);
  o.check = args.get_int("--check-gradient", 0,
                         "1: compare the gradient with central differences at the start and "
                         "exit (status 1 if the relative error exceeds 1e-6)",
                         0, 1) != 0;
  return o;
}

} // namespace dpgen_examples
