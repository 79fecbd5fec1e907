!> The seispulse library: closed-form and exact numerical answers for idealized near-fault
!> pulses and accelerograms. This facade re-exports the public API; `use seispulse`
!> is all a design code needs.
module seispulse
    use seispulse_kinds, only: dp, ik
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, SEISPULSE_SINGULAR, &
                                SEISPULSE_NO_CONVERGENCE, SEISPULSE_NO_BRACKET, &
                                SEISPULSE_INTERNAL, SEISPULSE_IO, SEISPULSE_NO_SOLUTION, status_name
    use seispulse_checks, only: outside, finite_positive, finite_at_least, positive, in_open, &
                                in_closed
    use seispulse_format, only: real_str, int_str, g_str, shortest_str, format_reals, NUM_LEN, &
                                upper
    use seispulse_number_reader, only: parse_real, NUM_OK, NUM_INVALID, NUM_RANGE
    use seispulse_special, only: expm1, log1p, exp_phis, exp_phis_scaled, phi2, phi3, sin_pi, &
                                 cos_pi, complex_phis, phi1, phi1_taylor, phi1_from_exp, &
                                 log1p_over_x, sinh_minus_x, x_minus_asinh, x_minus_sin, pi
    use seispulse_divided_differences, only: exp_dd1, exp_dd2, exp_dd_pack, cexp_dd1, &
                                             cexp_dd2_at0, cexp_dd2, cexp_dd3
    use seispulse_roots, only: scalar_function, find_root, smooth_function, find_root_newton, &
                               find_minimum
    use seispulse_ode, only: ode_system, ode_dop853_t, ode_dense_t, ode_dop853_factor, &
                             ode_fd_jacobian
    use seispulse_radau, only: ode_radau5_t, ode_radau5_factor, radau5_solve
    use seispulse_lapack, only: solve_linear
    use seispulse_pulses, only: exp_pulse, exp_pulse_point, exp_pulse_peaks, &
                                exp_pulse_impulse_amplitude, pulse_t, pulse_validate, pulse_eval, &
                                pulse_at, pulse_breaks, pulse_end_time, pulse_kind_from_name, &
                                pulse_kind_name, exponential_pulse, half_sine_pulse, &
                                sine_cycle_pulse, cosine_cycle_pulse, rectangular_pulse, &
                                triangular_pulse, ricker_pulse, mp_pulse, PULSE_EXPONENTIAL, &
                                PULSE_HALF_SINE, PULSE_SINE_CYCLE, PULSE_COSINE_CYCLE, &
                                PULSE_RECTANGULAR, PULSE_TRIANGULAR, PULSE_RICKER, PULSE_MP, &
                                pulse_peak_accel, pulse_accel, ricker_accel, ricker_window
    use seispulse_sliding_sim, only: friction_t, slide_t, stickslip_result_t, friction_validate, &
                                     stickslip_pulse, stickslip_record
    use seispulse_sliding_closed, only: half_cycle_t, full_cycle_t, sliding_block_t, yield_time, &
                                        half_cycle, full_cycle, inclined_resistances, &
                                        block_response, block_response_eta, half_cycle_integrated, &
                                        full_cycle_integrated, summarize_slides, eta_critical, &
                                        eta_critical_regression, full_cycle_peak_regression, &
                                        rectangle_half, rectangle_full, triangle_half, &
                                        spike_velocity_ratio, sliding_regime_name, &
                                        sliding_mode_name, SLIDING_REGIME_NONE, &
                                        SLIDING_REGIME_FORCED, SLIDING_REGIME_FREE, &
                                        SLIDING_MODE_NO_SLIDING, SLIDING_MODE_UNILATERAL, &
                                        SLIDING_MODE_STICK, SLIDING_MODE_SLIP, SLIDING_MODE_STUCK, &
                                        SLIDING_MODE_REVERSE_ONLY
    use seispulse_sliding_norm, only: characteristic_length, basic_lengths, table_1_2_exponents, &
                                      table_1_3
    use seispulse_rocking_closed, only: ROCK_NONE, ROCK_O1, ROCK_O2, ROCK_O3, ROCK_S1, ROCK_S2, &
                                        rocking_region_name, uplift_time, rocking_response, &
                                        stability_wall, stability_wall_inverse, overturn_boundary, &
                                        overturn_boundary_inverse, s1_s2_boundary, &
                                        rocking_classify, critical_time, time_of_max, &
                                        max_rotation, impact_time, rocking_summary, &
                                        rocking_extremes, rect_time_of_max_normalized, &
                                        rect_max_rotation_normalized, rect_impact_time_normalized
    use seispulse_rocking_sim, only: rocking_block_t, rocking_run_t, rectangular_block, &
                                     symmetric_block, rocking_block_validate, rock_pulse, &
                                     rock_record, overturning_map, ROCK_RUN_REST, &
                                     ROCK_RUN_NO_UPLIFT, ROCK_RUN_OVERTURN_NO_IMPACT, &
                                     ROCK_RUN_OVERTURN_ONE_IMPACT, ROCK_RUN_OVERTURN_MANY, &
                                     ROCK_RUN_TIME_LIMIT
    use seispulse_cylinder, only: rocking_body_t, cylinder_props, block_props, &
                                  body_rocking_block, equivalent_cylinder, equivalent_block, &
                                  rigid_pushover, normalized_pushover, body_overturning_map, &
                                  map_difference, overturning_threshold, BODY_SOLID_CYLINDER, &
                                  BODY_HOLLOW_CYLINDER, BODY_CUSTOM, BODY_BLOCK, &
                                  MAP_AXES_DIMENSIONLESS, MAP_AXES_DIMENSIONAL, MAP_DIFF_SAME, &
                                  MAP_DIFF_ONLY_FIRST, MAP_DIFF_ONLY_SECOND, MAP_DIFF_OTHER_MODE
    use seispulse_cylinder_roll, only: cylinder_roll, roll_run_t, roll_output_name, &
                                       roll_outcome_name, ROLL_NOUT, ROLL_OUT_THETA, &
                                       ROLL_OUT_PSI, ROLL_OUT_SPIN, ROLL_OUT_THETA_RATE, &
                                       ROLL_OUT_PSI_RATE, ROLL_OUT_SPIN_RATE, ROLL_OUT_XP, &
                                       ROLL_OUT_YP, ROLL_OUT_XG, ROLL_OUT_YG, ROLL_OUT_NORMAL, &
                                       ROLL_OUT_FRICTION, ROLL_OUT_ENERGY, ROLL_RUN_REST, &
                                       ROLL_RUN_NO_UPLIFT, ROLL_RUN_OVERTURN, ROLL_RUN_TIME_LIMIT
    use seispulse_winkler_contact, only: FOOTING_CIRCLE, FOOTING_RECTANGLE, strip_moments
    use seispulse_winkler, only: K_CONSTANT, K_VARYING, AXIS_LONG, AXIS_SHORT, WP_THETA, WP_B, &
                                 WP_POLE, WP_AREA, WP_SETTLEMENT, WP_K, WP_M_FOUND, WP_M_IMPOSED, &
                                 WP_FORCE, WP_NCOL, winkler_pushover_t, &
                                 halfspace_rocking_stiffness, winkler_modulus_circle, &
                                 rect_rocking_stiffness, winkler_modulus_rect, shape_factor, &
                                 varying_modulus, winkler_pushover, block_winkler_pushover, &
                                 winkler_master_curve, winkler_equivalent_cylinder
    use seispulse_clay_footing, only: degradation_coeffs_t, inelastic_pushover_t, clay_bearing, &
                                      initial_stiffness_ratio, gaussian_correction, &
                                      theta_uplift, inelastic_pushover, moment_capacity_circle, &
                                      IP_THETA, IP_K_R, IP_M_FOUND, IP_M_IMPOSED, IP_FORCE, IP_X, &
                                      IP_G, IP_NCOL, CAPACITY_TC00_PEAK, &
                                      CAPACITY_EFFECTIVE_WIDTH, NC_CIRCLE_CLAY, &
                                      CHI_ELASTIC_LIMIT, SF_WEAK_LIMIT
    use seispulse_winkler_rock, only: winkler_model_t, winkler_run_t, winkler_model, &
                                      winkler_rock, winkler_overturning_map, &
                                      winkler_outcome_name, winkler_output_name, &
                                      winkler_contact_forces, winkler_rhs_jacobian, &
                                      winkler_barrier, DAMP_ROCKING, DAMP_VERTICAL, WR_OUT_V, &
                                      WR_OUT_THETA, WR_OUT_V_RATE, WR_OUT_THETA_RATE, &
                                      WR_OUT_WIDTH, WR_OUT_NORMAL, WR_OUT_MOMENT, WR_OUT_ACCEL, &
                                      WR_OUT_ENERGY, WR_OUT_WORK, WR_OUT_DISSIPATED, WR_NOUT, &
                                      WR_RUN_SAFE, WR_RUN_OVERTURN_NO_IMPACT, &
                                      WR_RUN_OVERTURN_ONE_IMPACT, WR_RUN_OVERTURN_IMPACTS, &
                                      WR_RUN_TIME_LIMIT
    use seispulse_records, only: record_t, read_record, record_pga, pga_scale_factor, &
                                 ground_motion, record_format_name, record_units_name, &
                                 RECORD_AUTO, RECORD_AT2, RECORD_SLAMMER, RECORD_COLUMN, &
                                 RECORD_TIME_ACCEL, UNITS_G, UNITS_M_S2, UNITS_CM_S2, &
                                 STANDARD_GRAVITY, accel_unit_code, accel_unit_factor, &
                                 ACCEL_UNIT_NAMES, MAX_RECORD_SAMPLES, MAX_RECORD_BYTES
    use seispulse_intensity, only: intensity_t, record_intensity, spectral_acceleration, &
                                   mean_period, TM_F_LOW, TM_F_HIGH, TM_DF_MAX, TM_MAX_POINTS
    use seispulse_fft, only: fft, next_power_of_two, is_power_of_two
    use seispulse_newmark, only: newmark_block_t, newmark_result_t, newmark_rigid, &
                                 newmark_incline, newmark_block_validate, newmark_mode_name, &
                                 newmark_method_name, newmark_mode_code, newmark_method_code, &
                                 NEWMARK_DOWN, NEWMARK_BOTH, NEWMARK_ASYM, NEWMARK_EXACT, &
                                 NEWMARK_SLAMMER
    use seispulse_flexible_model, only: flexible_mass_t, flexible_result_t, modal_peak_t, &
                                        flexible_mass_validate, radiation_damping, &
                                        eql_properties, ky_table_validate, eql_iterate, &
                                        masing_damping_pct, flexible_soil_name, &
                                        flexible_soil_code, SOIL_LINEAR, &
                                        SOIL_EQUIVALENT_LINEAR, FLEX_SLAMMER, FLEX_EXACT
    use seispulse_flexible, only: flexible_decoupled, flexible_coupled
    use seispulse_empirical, only: jibson_1993, jibson_1998, jibson_2007_ratio, &
                                   jibson_2007_ratio_m, jibson_2007_arias, &
                                   jibson_2007_arias_ratio, ambraseys_menu_1988, &
                                   saygili_rathje_2008_pga, saygili_rathje_2008_pgv, &
                                   saygili_rathje_2008_pgv_arias, rathje_saygili_2009, &
                                   sr08_pgv_sigma, sr08_pgv_arias_sigma, rs09_sigma, &
                                   bt07_ln_disp, bt07_p_zero, bt07_p_zero_slammer, &
                                   ra11_kmax_ratio, ra11_kvelmax_ratio, probability_of_failure, &
                                   empirical_rigid, empirical_model_name, empirical_model_code, &
                                   empirical_needs, empirical_check, bray_travasarou_2007, &
                                   rathje_antonakos_2011, probability_of_failure_checked, &
                                   EMP_JIBSON_1993, EMP_JIBSON_1998, EMP_JIBSON_2007_RATIO, &
                                   EMP_JIBSON_2007_RATIO_M, EMP_JIBSON_2007_ARIAS, &
                                   EMP_JIBSON_2007_ARIAS_RATIO, EMP_AMBRASEYS_MENU_1988, &
                                   EMP_SR08_PGA, EMP_SR08_PGA_PGV, EMP_SR08_PGA_PGV_ARIAS, &
                                   EMP_RS09_PGA_M, EMP_RIGID_MODELS, EMP_LOG10, EMP_LN, &
                                   EMP_RA11_PGA_M, EMP_RA11_PGA_PGV, EMP_NEED_PGA, EMP_NEED_PGV, &
                                   EMP_NEED_ARIAS, EMP_NEED_M, J93_SIGMA, J98_SIGMA, &
                                   J07_RATIO_SIGMA, J07_RATIO_M_SIGMA, J07_ARIAS_SIGMA, &
                                   J07_ARIAS_RATIO_SIGMA, AM88_SIGMA, SR08_PGA_SIGMA, BT07_SIGMA, &
                                   BT07_TS_RIGID
    use seispulse_sdof_sim, only: sdof_step_t, sdof_step, sdof_validate, sdof_response, &
                                  sdof_spectrum, pseudo_spectra, design_envelope, spectral_shape, &
                                  sdof_threads, SDOF_PEAKS_EXACT, SDOF_PEAKS_SAMPLES
    use seispulse_sdof_closed, only: dynamic_coefficient, harmonic_response, rect_pulse_response, &
                                     beta_pulse, impulse_max, impulse_response, &
                                     sdof_pulse_response, sdof_pulse_peaks, sdof_pulse_spectrum, &
                                     BETA_HYSTERETIC, BETA_VISCOUS, HARMONIC_SINE, &
                                     HARMONIC_COSINE, BETA_PULSE_TEXTBOOK, BETA_PULSE_EXACT
    use seispulse_walls_common, only: wall_psi_t, wall_psi, free_field_frequencies
    use seispulse_walls_vy, only: vy_default_tol, vy_min_tol, vy_max_tol, vy_max_omega_ratio, &
                                  vy_rigid, vy_rigid_sweep, vy_pressure, vy_fields
    use seispulse_walls_one_term, only: WALL_SHAPE_LINEAR, WALL_SHAPE_SINE, WALL_SHAPE_PARABOLIC, &
                                        WALL_SHAPE_POWER, one_term_shape_t, one_term_t, &
                                        one_term_shape, one_term, one_term_sweep, &
                                        one_term_pressure, one_term_displacement, &
                                        power_law_fundamental, power_law_cutoff, winkler_one_term, &
                                        winkler_dashpot, winkler_scott, winkler_vy
    use seispulse_codes, only: ec8_seismic_coefficients, ec8_vertical_ratio, ec8_r_factor, &
                               mononobe_okabe, ec8_thrust_t, ec8_thrust, westergaard_pressure, &
                               ec8_rigid_thrust, seed_whitman_increment, wood_thrust, &
                               ec8_ground_parameters, ec8_damping_correction, ec8_check_damping, &
                               ec8_elastic_spectrum, ec8_design_spectrum, EC8_WALL_GRAVITY_300, &
                               EC8_WALL_GRAVITY_200, EC8_WALL_RESTRAINED, WATER_DRY, &
                               WATER_IMPERVIOUS, WATER_PERMEABLE, EC8_SPECTRUM_TYPE_1, &
                               EC8_SPECTRUM_TYPE_2, EC8_GROUND_A, EC8_GROUND_B, EC8_GROUND_C, &
                               EC8_GROUND_D, EC8_GROUND_E, EC8_ANNEX_RECOMMENDED, EC8_ANNEX_GR, &
                               ec8_reference_pga, ec8_design_ag
    use seispulse_eak2000, only: eak2000_ground_parameters, eak2000_zone_acceleration, &
                                 eak2000_importance_factor, eak2000_damping_correction, &
                                 eak2000_check_damping, eak2000_design_spectrum, &
                                 eak2000_elastic_spectrum, EAK_GROUND_A, EAK_GROUND_B, &
                                 EAK_GROUND_C, EAK_GROUND_D, EAK_GROUND_X, EAK_MAP_2003, &
                                 EAK_MAP_2000, EAK_BETA0, EAK_ZONES_2003
    use seispulse_record_suite, only: SUITE_FIT_LINEAR, SUITE_FIT_LOG, suite_rtol, suite_check_t, &
                                      suite_check_periods, ec8_suite_check, SUITE_TARGET_EC8, &
                                      SUITE_TARGET_EAK, SUITE_RULE_PGA, SUITE_RULE_SPECTRUM, &
                                      suite_target_t, suite_target_values, suite_target_pga, &
                                      suite_target_corners, suite_refine_margin, &
                                      suite_refine_spacings, &
                                      suite_records_room, ec8_suite_check_records, &
                                      suite_records_grid, SUITE_SPECTRUM_FRACTION
    use seispulse_wall_table, only: wall_case_t, wall_case_default, wall_comparison, &
                                    wall_pressure_profile, wall_row_label, WALL_ROWS, &
                                    WALL_PROFILE_COLUMNS
    implicit none
    public

    !> Library version, as in meson.build.
    character(len=*), parameter :: seispulse_version = '0.1.0'

end module seispulse
