// a34_readback_before_store: dpgen must reject this kernel (no test).
