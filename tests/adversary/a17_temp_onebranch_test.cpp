// a17_temp_onebranch: dpgen must reject this kernel (no test).
