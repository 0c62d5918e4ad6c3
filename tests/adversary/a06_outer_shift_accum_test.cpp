// a06_outer_shift_accum: dpgen must reject this kernel (no test).
