// a10_flux_read_beyond: dpgen must reject this kernel (no test).
