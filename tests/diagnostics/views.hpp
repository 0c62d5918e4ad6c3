// View classes that are not layouts, for views.cpp.
#pragma once

// Toeplitz-like: v(j, i) = p[i + j], so (j, i) and (j + 1, i - 1) are one element.
struct Diagonal {
  double* p;
  double& operator()(int j, int i) const { return p[i + j]; }
};

// The index goes through a function dpgen cannot see into.
int scramble(int i);
struct Scrambled {
  double* p;
  double& operator()(int i) const { return p[scramble(i)]; }
};

// A layout, but indexed with five indices.
struct Five {
  double* p;
  int s1, s2, s3, s4;
  double& operator()(int a, int b, int c, int d, int e) const {
    return p[a * s4 + b * s3 + c * s2 + d * s1 + e];
  }
};

struct Box2 {
  int n;
};
