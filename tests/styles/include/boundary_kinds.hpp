// The boundary kinds of tests/styles/enum_params.cpp: an enum class in a
// header, as codes keep their configuration types.
#pragma once

enum class Bc { Zero, Copy, Flip };
