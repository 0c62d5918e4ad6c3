// r5_mm_out_no_init: dpgen must reject this kernel (no test).
