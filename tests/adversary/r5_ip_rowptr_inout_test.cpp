// r5_ip_rowptr_inout: dpgen must reject this kernel (no test).
