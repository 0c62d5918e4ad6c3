# The adversarial kernels ctest builds (tests/adversary/CMakeLists.txt) and
# the fuzz target runs as seeds (tests/fuzz/CMakeLists.txt): the regressions,
# accepted with right adjoints, and the ones rejected with a diagnostic.
set(DPGEN_ADVERSARY_REGRESSIONS
    guard_continue_times cond_idx_gt0 cond_readback cond_index_overwrite cond_readback_else
    cond_plus_readback
    cond_nested readback_square a33_cond_store_index a36_cond_store_idx_min
    a42_null_adj a43_helper_sq_nested_crash_min a08_straight_k_before reduce_into_other
    split_pre_reader split_reduce_plus split_norm_other
    r3_min_rowptr_rev_row r3_min_rowptr_rev_out r3_ld_rev_out r3_szt_countdown_gt0
    r3_periodic_ternary_uns r3_inout_stride
    # round r4 (issue 20 constructs), accepted and right
    r4_acc_in_if_arm r4_acc_two_share_store r4_acc_nested_rowsums r4_acc_later_nest_and_local
    r4_tri_countdown_inner r4_tri_window_moving r4_par_ij_mod3 r4_par_unroll_odd
    r4_lam_calls_lambda r4_arr_in_lambda r4_br_arm_output_as_work r4_rp_colsum_into_row0
    r4_mac_local_changes r4_nm_counter_i_1 r4_nm_scalarised_array_clash
    r4_min_local_dpgen_prefix_hang r4_br_ne_vs_eq r4_min_le_min_bound r4_arr_buffer_then_reverse
    r4_acc_max
    # round r5 (line buffers: local arrays of more than 64 elements, VLAs), accepted and right
    r5_buffers
    # round r5 (min/max reductions, pinned stores, later writer, in place across nests)
    r5_mm_start_a0_ties r5_mm_cond_data_path_ties r5_mm_continue_ties r5_mm_float_near_ties
    r5_mm_rowmax_softmax r5_mm_err_ptr_later_loop r5_pin_strided_last_maybe_missing
    r5_pin_diag_elem r5_lw_coef2_overlap r5_ip_2d_fluxes_omp r5_ip_max_ties
    r5_min_lw_countdown r5_min_mm_ternary_oob r5_ip_pinned_update
    # refused until strided loops could count down (i -= 2), now accepted and right
    r3_step2_down r4_par_countdown_step2
    # refused until switch statements were in the subset, now accepted and right
    r4_br_switch
    # accepted, but its run-time layout check threw for every n >= 3 (corpus 20)
    c20_strided_down_overwrite
    # its interior cells stored empty sums outside an empty array (nx = 0)
    c20_row_start_read
    # accepted with wrong adjoints in round r5, then refused; since 2026-12-01 accepted
    # and right (a sum or max updated in a helper's `double&`/`double*` or a lambda)
    r5_min_helper_ptr_accum r5_mm_helper_ref_update r5_mm_lambda_ref_capture
    # refused until pointer locals and pointer arguments were in the subset (2026-12-01):
    # `put(&o[i + 1], x)`, `lap(u + 1, i - 1)` in a helper, `const double* ap = a + 1;`
    r3_helper_ptr_elem helper_ptr_offset ptr_arith
    # refused until std::vector kernels could have work arrays (2026-12-02)
    r3_vector_work
    # refused by a conversion check that missed a std::array subscript (`b[m % 2]` of an
    # unrolled counter: "may go below zero") until 2026-12-02
    r4_arr_accum_buffer)
# Rejected with a diagnostic (they were accepted with wrong adjoints).
set(DPGEN_ADVERSARY_REJECTED
    scale_after_reduce reduce_sqrt reduce_ptr_star reduce_then_assign nest_scale_after
    split_matvec_square a10_flux_read_beyond a38_accum_only_work a39_read_beyond_nonlin
    r3_min_uns_cond_wrap r3_min_uns_cond_im1 r3_min_cast_unsigned r3_min_int_vs_uns
    r3_min_uns_local r3_min_szt_min_wrap r3_min_uns_value r3_min_short_local
    # round r4: recurrences, stale lambda copies, overlapping writes, output read back
    r4_acc_linear_recurrence r4_acc_second_loop_same r4_lam_copy_local_changes
    r4_lam_scalar_copy_in_loop_changes r4_lam_loop_inside r4_tri_forward_subst
    r4_tri_symmetric_fill r4_par_red_then_black r4_rp_ghost_both r4_nm_params_adj_dot
    r4_br_overlapping_conds r4_min_lam_array_copy_stale r4_min_lam_mutable_state
    # round r5: values assigned through a helper or a lambda in a loop, a pin
    # by two counters, an in-place update under a condition on a sum
    r5_min_helper_ref_after_loop r5_min_lambda_ref_after_loop r5_min_helper_recurrence
    r5_min_pin_two_counters r5_min_ip_cond_on_sum)
