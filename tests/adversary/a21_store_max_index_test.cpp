// a21_store_max_index: dpgen must reject this kernel (no test).
