# The style kernels ctest builds and tests (tests/styles/CMakeLists.txt) and the fuzz target runs
# as seeds whose generated code the build compiles (tests/fuzz/CMakeLists.txt).
if(NOT DEFINED DPGEN_STYLE_KERNELS)
  set(DPGEN_STYLE_KERNELS
      advect_minmod_helper advect_upwind_ptrscalars advect_vanleer_helper burgers_private_temps
      diffusion2d_bounds_params divergence_accumulate2d flux_readback flux_rows_two_inner
      spelled_sums heat1d_c89 heat1d_ends heat1d_float_omp heat2d_c89 heat2d_restrict heat_source_readback
      heat_typedef hydro_flux_xminmax jacobi2d_array2d jacobi2d_guard laplace3d_interior_intflat
      pdv_ptrscalars prolong1d_size_t rhs_accumulate shallow_water_lf smooth_then_scale
      smooth_weights_localarray twin_kernels twin_limiter_kernels two_loops_minimal
      two_nests_renamed two_nests_repro upwind_unsigned varcoef_laplace2d_rowarray
      varcoef_poisson3d_c89 viscosity_linebuffer wave1d_boundary_stores wave2d_float_restrict
      wave_typedef_float burgers_rk2_workarray hydro_twopass_workarray gradient_vector
      heat_vector grad_staggered_rowptr restrict2d_rowptr wave2d_rowptr_scattered
      heat3d_planes_scattered ghost_rows_rowptr edge_rows_rowptr names_like_generated
      pdv_predict_branches advect_dir_branches flux_calc_idx_macro accumulators triangular
      parity_loops std_array_table lambdas end_columns view_laplace2d view_fortran3d
      view_field1d member_advect member_functor minmax_reductions last_writer line_buffers
      component_planes pow2_bits window_moments table_offsets view_workarrays shifted_quotients
      static_tables clamp_limiter compound_scale accessor_local multi_counters
      range_for_tables switch_cases nested_vectors nested_escapes wide_constants
      enum_params running_index flux_sums view_branches guarded_reads arm_locals
      member_inplace local_chains cond_operand_calls early_returns scatter_reads
      lambda_accumulators loop_local_bounds pointer_locals checked_probe c89_row_pointers
      cpp_idioms vector_sums while_loops clamped_indices vector_buffers)
endif()
# Style kernels written in C (<name>.c, parsed as C: VLAs, C99 pointer casts),
# each with a <name>_test.cpp like the others.
if(NOT DEFINED DPGEN_STYLE_C_KERNELS)
  set(DPGEN_STYLE_C_KERNELS line_buffers_c)
endif()
