#!/usr/bin/env python3
"""The driver of scripts/compare_results.sh: C++ that calls every flat entry
point `<name><suffix>(...)` a generated header declares, each with seeded
random inputs (arrays of 2^21 doubles or floats in [-1, 1), scalars in [0.3, 1.7),
integers = N), and prints a hash (FNV-1a) of every array it writes, so that
two generated versions can be compared bit for bit.
  compare_results_driver.py HEADER SUFFIX N > driver.cpp
"""
import re, sys
hdr, suffix, n = sys.argv[1], sys.argv[2], int(sys.argv[3])
text = open(hdr).read()
decls = re.findall(r'^(?:void|double|float) (\w+' + suffix + r')\(([^;{]*)\);', text, re.M)
out = ['#include "%s"' % hdr.split('/')[-1], '#include <cstdio>', '#include <cstring>',
       '#include <random>', '#include <stdexcept>', '#include <vector>',
       'static const size_t N = size_t(1) << 21;',
       'template <typename T> static void dump(const char* fn, const char* a, const T* p) {',
       '  unsigned long long h = 1469598103934665603ull; const unsigned char* b = (const unsigned char*)p;',
       '  for (size_t i = 0; i < N * sizeof(T); ++i) { h ^= b[i]; h *= 1099511628211ull; }',
       '  std::printf("%s %s %016llx\\n", fn, a, h); }',
       'int main() {', '  std::mt19937_64 rng(7); std::uniform_real_distribution<double> U(-1, 1), P(0.3, 1.7);']
for name, params in decls:
    ps = [p.strip() for p in params.replace('\n', ' ').split(',')]
    if any('&' in p or 'std::' in p or '(*' in p or '**' in p or 'const*' in p for p in ps):
        out.append('  // skipped %s (shaped parameters)' % name); continue
    body, args, dumps = [], [], []
    for p in ps:
        m = re.match(r'(const )?(double|float|int|long|std::ptrdiff_t|size_t|unsigned)(\*)? (\w+)$', p)
        if not m:
            body = None; break
        const, ty, ptr, nm = m.groups()
        if ptr:
            if ty not in ('double', 'float'): body = None; break
            body.append('  std::vector<%s> %s(N); for (auto& x : %s) x = %s(U(rng));' % (ty, nm, nm, ty))
            args.append(nm + '.data()')
            if not const: dumps.append(nm)
        elif ty in ('double', 'float'):
            body.append('  const %s %s = P(rng);' % (ty, nm)); args.append(nm)
        else:
            body.append('  const %s %s = %d;' % (ty, nm, n)); args.append(nm)
    if body is None:
        out.append('  // skipped %s (parameter types)' % name); continue
    out.append('  {')
    out += body
    out.append('  try { %s(%s); } catch (const std::exception& e) { std::printf("%s threw %%s\\n", e.what()); }' % (name, ', '.join(args), name))
    for d in dumps:
        out.append('  dump("%s", "%s", %s.data());' % (name, d, d))
    out.append('  }')
out.append('}')
print('\n'.join(out))
