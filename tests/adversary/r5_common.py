# Helpers of specs_r5.py: hand-computed tie tests (exact ties, where finite
# differences are one-sided and the check_adjoint harness cannot look).
def fmt(v, T):
    return ", ".join(("%sf" % repr(float(x))) if T == "float" else repr(float(x)) for x in v)

def tie_case(title, fname, params, inputs, vals, expect_out, expect_adj, seed_out, seed_index=0,
             T="double", tangent=True):
    """params: the spec's params; inputs: {in-name: [values]}; vals: {val-name: C++ expr};
    expect_out: {out-name: {index: value}} checked on the forward; expect_adj: {in-name: [values]}
    for the seed 1 at seed_out[seed_index]; the tangent in each unit direction must give the same."""
    L = ['TEST_CASE("adversary: %s ties") {' % title]
    outsz = {}
    for p in params:
        if p[0] == "val":
            L.append("  const auto %s = %s;" % (p[1], vals[p[1]]))
    for p in params:
        if p[0] == "in":
            v = inputs[p[1]]
            L.append("  std::vector<%s> %s = {%s};" % (T, p[1], fmt(v, T)))
            L.append("  std::vector<%s> %s_adj(%d, 0), %s_dir(%d, 0);" % (T, p[1], len(v), p[1], len(v)))
        elif p[0] == "out":
            z = "size_t(%s)" % p[2]
            L.append("  std::vector<%s> %s(%s, 0), %s_seed(%s, 0), %s_t(%s, 0), %s_dot(%s, 0);" %
                     (T, p[1], z, p[1], z, p[1], z, p[1], z))
            outsz[p[1]] = p[2]
    L.append("  %s_seed[%d] = 1;" % (seed_out, seed_index))
    fw, ad, tg = [], [], []
    for p in params:
        if p[0] == "in":
            fw.append("%s.data()" % p[1]); ad += ["%s.data()" % p[1], "%s_adj.data()" % p[1]]
            tg += ["%s.data()" % p[1], "%s_dir.data()" % p[1]]
        elif p[0] == "out":
            fw.append("%s.data()" % p[1]); ad.append("%s_seed.data()" % p[1])
            tg += ["%s_t.data()" % p[1], "%s_dot.data()" % p[1]]
        else:
            fw.append(p[1]); ad.append(p[1]); tg.append(p[1])
    eps = "1e-5" if T == "float" else "1e-12"
    L.append("  %s(%s);" % (fname, ", ".join(fw)))
    for o, d in expect_out.items():
        for i, v in d.items():
            L.append("  CHECK(double(%s[%d]) == doctest::Approx(%r).epsilon(%s));" % (o, i, float(v), eps))
    L.append("  %s_adjoint(%s);" % (fname, ", ".join(ad)))
    for a, v in expect_adj.items():
        for i, x in enumerate(v):
            L.append("  CHECK_MESSAGE(double(%s_adj[%d]) == doctest::Approx(%r).epsilon(%s), \"adjoint %s[%d]\");" % (a, i, float(x), eps, a, i))
    if tangent:
        for a, v in expect_adj.items():
            for i, x in enumerate(v):
                L.append("  { std::fill(%s_dot.begin(), %s_dot.end(), %s(0)); %s_dir[%d] = 1; %s_tangent(%s); %s_dir[%d] = 0;"
                         % (seed_out, seed_out, T, a, i, fname, ", ".join(tg), a, i))
                L.append("    CHECK_MESSAGE(double(%s_dot[%d]) == doctest::Approx(%r).epsilon(%s), \"tangent along %s[%d]\"); }"
                         % (seed_out, seed_index, float(x), eps, a, i))
    L.append("}")
    return "\n".join(L)
