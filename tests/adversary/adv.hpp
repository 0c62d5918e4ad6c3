// Shared includes of the adversary tests (tests/adversary/README.md).
#pragma once
#include "support/adjoint_check.hpp"

#include "dpgen/annotate.hpp"

#include <cstddef>
#include <stdexcept>
#include <vector>

#define ADV_SZ(x) static_cast<size_t>(x)
