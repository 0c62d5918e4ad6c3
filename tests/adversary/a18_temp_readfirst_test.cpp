// a18_temp_readfirst: dpgen must reject this kernel (no test).
