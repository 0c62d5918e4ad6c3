// A small command-line parser for the examples: --name value options with
// defaults, --help, and a clear error for anything unknown or malformed.
#pragma once

#include <cstdlib>
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

  int get_int(const std::string& name, int def, const std::string& help) {
    std::string v = get(name, std::to_string(def), help);
    char* end = nullptr;
    long r = std::strtol(v.c_str(), &end, 10);
    if (v.empty() || *end)
      throw std::invalid_argument(program_ + ": " + name + " expects an integer, got '" + v + "'");
    return static_cast<int>(r);
  }

  double get_double(const std::string& name, double def, const std::string& help) {
    std::string v = get(name, format(def), help);
    char* end = nullptr;
    double r = std::strtod(v.c_str(), &end);
    if (v.empty() || *end)
      throw std::invalid_argument(program_ + ": " + name + " expects a number, got '" + v + "'");
    return r;
  }

  std::string get_string(const std::string& name, const std::string& def,
                         const std::string& help) {
    return get(name, def, help);
  }

  /// Call after every get_*: prints help (returns true) or rejects unknown
  /// options.
  bool finish() {
    if (help_) {
      std::printf("%s\n\nusage: %s [options]\n\n", about_.c_str(), program_.c_str());
      for (const auto& l : usage_)
        std::printf("%s\n", l.c_str());
      return true;
    }
    for (const auto& [k, v] : given_)
      if (!known_.count(k))
        throw std::invalid_argument(program_ + ": unknown option " + k + " (see --help)");
    return false;
  }

private:
  std::string get(const std::string& name, const std::string& def, const std::string& help) {
    known_[name] = true;
    usage_.push_back("  " + name + " (default " + (def.empty() ? "none" : def) + ")\n      " + help);
    auto it = given_.find(name);
    return it == given_.end() ? def : it->second;
  }
  static std::string format(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
  }

  std::string program_, about_;
  std::map<std::string, std::string> given_;
  std::map<std::string, bool> known_;
  std::vector<std::string> usage_;
  bool help_ = false;
};

/// The options every example has besides its own.
struct CommonOptions {
  std::string csv;         ///< --csv: the training log
  std::string out;         ///< --out: folder for pictures
  double require = 0;      ///< --require-reduction: fail below this loss ratio
  bool check = false;      ///< --check-gradient: compare with central differences and exit
};

inline CommonOptions common_options(Args& args, const std::string& name) {
  CommonOptions o;
  o.csv = args.get_string("--csv", "", "CSV log path (iter,loss,grad_norm,seconds)");
  o.out = args.get_string("--out", "out/" + name, "folder for pictures");
  o.require = args.get_double("--require-reduction", 0,
                              "exit with an error unless the loss drops by this factor");
  o.check = args.get_int("--check-gradient", 0,
                         "1: compare the gradient with central differences at the start and "
                         "exit (status 1 if the relative error exceeds 1e-6)") != 0;
  return o;
}

} // namespace dpgen_examples
