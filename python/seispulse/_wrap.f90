!> Thin f2py layer: plain external subroutines with explicit-shape arrays, scalar
!> integer/double/fixed-length character arguments only, `stat` + `errmsg` out.
!> No numerics here: each routine translates its arguments and calls the library
!> (style.md section 3: f2py cannot pass derived types, optionals or allocatables).

!> Exponential pulse, dimensionless; beta has length 1 or n.
subroutine sp_exp_pulse(n, tau, nb, beta, full, a, v, d, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_pulses, only: exp_pulse
    implicit none
    integer, intent(in) :: n, nb, full
    real(dp), intent(in) :: tau(n), beta(nb)
    real(dp), intent(out) :: a(n), v(n), d(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call exp_pulse(tau, beta, full /= 0, a, v, d, stat, errmsg)
end subroutine sp_exp_pulse

!> Peak velocity and displacement of the exponential pulse, per beta.
subroutine sp_exp_pulse_peaks(n, beta, full, vg, dg, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_pulses, only: exp_pulse_peaks
    implicit none
    integer, intent(in) :: n, full
    real(dp), intent(in) :: beta(n)
    real(dp), intent(out) :: vg(n), dg(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    integer :: i
    errmsg = ''
    stat = SEISPULSE_SUCCESS
    do i = 1, n
        call exp_pulse_peaks(beta(i), full /= 0, vg(i), dg(i), stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
    end do
end subroutine sp_exp_pulse_peaks

!> Unit-impulse amplitude of the exponential pulse, per beta.
subroutine sp_exp_pulse_impulse_amplitude(n, beta, amp, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_pulses, only: exp_pulse_impulse_amplitude
    implicit none
    integer, intent(in) :: n
    real(dp), intent(in) :: beta(n)
    real(dp), intent(out) :: amp(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    integer :: i
    errmsg = ''
    stat = SEISPULSE_SUCCESS
    do i = 1, n
        call exp_pulse_impulse_amplitude(beta(i), amp(i), stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
    end do
end subroutine sp_exp_pulse_impulse_amplitude

!> Any pulse in SI units; params(np, 9) packed as in pulse_from_params, np = 1 or n.
subroutine sp_pulse_eval(kind, n, t, np, params, a, v, d, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_pulses, only: pulse_t, pulse_eval, pulse_from_params, PULSE_NPARAM
    implicit none
    integer, intent(in) :: kind, n, np
    real(dp), intent(in) :: t(n), params(np, PULSE_NPARAM)
    real(dp), intent(out) :: a(n), v(n), d(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    integer :: i
    errmsg = ''
    if (np == 1) then
        call pulse_eval(pulse_from_params(kind, params(1, :)), t, a, v, d, stat, errmsg)
    else
        stat = SEISPULSE_SUCCESS
        do i = 1, n
            call pulse_eval(pulse_from_params(kind, params(i, :)), t(i:i), a(i:i), v(i:i), &
                            d(i:i), stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
        end do
    end if
end subroutine sp_pulse_eval

!> Pulse kind code from its name.
subroutine sp_pulse_kind(name, kind, stat, errmsg)
    use seispulse_pulses, only: pulse_kind_from_name
    implicit none
    character(len=*), intent(in) :: name
    integer, intent(out) :: kind, stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call pulse_kind_from_name(name, kind, stat, errmsg)
end subroutine sp_pulse_kind

! ---------------------------------------------------------------------------------
! Sliding block (seispulse_sliding_closed); every array has length n (broadcast in Python)
! ---------------------------------------------------------------------------------

!> Onset time (Eq. 1.12, 1.34).
subroutine sp_yield_time(n, eta, beta, sfac, tau_y, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_sliding_closed, only: yield_time
    implicit none
    integer, intent(in) :: n
    real(dp), intent(in) :: eta(n), beta(n), sfac(n)
    real(dp), intent(out) :: tau_y(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    integer :: i
    errmsg = ''
    stat = SEISPULSE_SUCCESS
    do i = 1, n
        call yield_time(eta(i), beta(i), sfac(i), tau_y(i), stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
    end do
end subroutine sp_yield_time

!> Half-cycle response; regime codes as REGIME_*; method 0 closed forms, 1 integrator.
subroutine sp_half_cycle(n, eta, beta, sfac, method, tau_y, tau_m, regime, um, dugm, vm, &
                         stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_sliding_closed, only: half_cycle, half_cycle_integrated, half_cycle_t
    implicit none
    integer, intent(in) :: n, method
    real(dp), intent(in) :: eta(n), beta(n), sfac(n)
    real(dp), intent(out) :: tau_y(n), tau_m(n), um(n), dugm(n), vm(n)
    integer, intent(out) :: regime(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(half_cycle_t) :: r
    integer :: i
    errmsg = ''
    stat = SEISPULSE_SUCCESS
    do i = 1, n
        if (method == 0) then
            call half_cycle(eta(i), beta(i), sfac(i), r, stat, errmsg)
        else
            call half_cycle_integrated(eta(i), beta(i), sfac(i), r, stat, errmsg)
        end if
        if (stat /= SEISPULSE_SUCCESS) return
        tau_y(i) = r%tau_y
        tau_m(i) = r%tau_m
        regime(i) = r%regime
        um(i) = r%um
        dugm(i) = r%dugm
        vm(i) = r%vm
    end do
end subroutine sp_half_cycle

!> Full-cycle response; mode codes as MODE_*; out(:, 1:9) = tau_y1, tau_m1, um1, tau_y2,
!> tau_m2, um2, ures, vm1, vm2; method 0 closed forms, 1 integrator.
subroutine sp_full_cycle(n, eta1, eta2, beta, sfac, static_reverse, method, mode, out, stat, &
                         errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_sliding_closed, only: full_cycle, full_cycle_integrated, full_cycle_t
    implicit none
    integer, intent(in) :: n, static_reverse, method
    real(dp), intent(in) :: eta1(n), eta2(n), beta(n), sfac(n)
    integer, intent(out) :: mode(n)
    real(dp), intent(out) :: out(n, 9)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(full_cycle_t) :: r
    integer :: i
    errmsg = ''
    stat = SEISPULSE_SUCCESS
    do i = 1, n
        if (method == 0) then
            call full_cycle(eta1(i), eta2(i), beta(i), sfac(i), static_reverse /= 0, r, stat, &
                            errmsg)
        else
            call full_cycle_integrated(eta1(i), eta2(i), beta(i), sfac(i), static_reverse /= 0, &
                                       .true., r, stat, errmsg)
        end if
        if (stat /= SEISPULSE_SUCCESS) return
        mode(i) = r%mode
        out(i, :) = [r%tau_y1, r%tau_m1, r%um1, r%tau_y2, r%tau_m2, r%um2, r%ures, r%vm1, r%vm2]
    end do
end subroutine sp_full_cycle

!> Resistances and along-plane factors on an incline (Eq. 1.31).
subroutine sp_inclined(n, mu, ag, slope, xi, eta1, eta2, k1, k2, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_sliding_closed, only: inclined_resistances
    implicit none
    integer, intent(in) :: n
    real(dp), intent(in) :: mu(n), ag(n), slope(n), xi(n)
    real(dp), intent(out) :: eta1(n), eta2(n), k1(n), k2(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    integer :: i
    errmsg = ''
    stat = SEISPULSE_SUCCESS
    do i = 1, n
        call inclined_resistances(mu(i), ag(i), slope(i), xi(i), eta1(i), eta2(i), k1(i), &
                                  k2(i), stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
    end do
end subroutine sp_inclined

!> Stick/slip boundary: exact (method 0) or Eq. 1.22 (method 1).
subroutine sp_eta_critical(n, beta, method, eta_cr, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_sliding_closed, only: eta_critical, eta_critical_regression
    implicit none
    integer, intent(in) :: n, method
    real(dp), intent(in) :: beta(n)
    real(dp), intent(out) :: eta_cr(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    integer :: i
    errmsg = ''
    stat = SEISPULSE_SUCCESS
    do i = 1, n
        if (method == 0) then
            call eta_critical(beta(i), eta_cr(i), stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
        else
            eta_cr(i) = eta_critical_regression(beta(i))
        end if
    end do
end subroutine sp_eta_critical

!> Closed forms: which = 1 rectangle half (tau_m, um, um/dugm, vm), 2 rectangle full
!> (tau_m1, um1, tau_m2, um2, ures), 3 triangle half (tau_y, tau_m, um, vm, regime),
!> 4 spike (vm), 5 regression 1.30 (um/D_g; beta in out(:, 1) on entry). eta in (0, 1).
subroutine sp_limit_form(n, which, eta, out)
    use seispulse_kinds, only: dp
    use seispulse_sliding_closed, only: rectangle_half, rectangle_full, triangle_half, &
                                 spike_velocity_ratio, full_cycle_peak_regression
    implicit none
    integer, intent(in) :: n, which
    real(dp), intent(in) :: eta(n)
    real(dp), intent(inout) :: out(n, 5)
    integer :: regime(n)
    select case (which)
    case (1)
        call rectangle_half(eta, out(:, 1), out(:, 2), out(:, 3), out(:, 4))
    case (2)
        call rectangle_full(eta, out(:, 1), out(:, 2), out(:, 3), out(:, 4), out(:, 5))
    case (3)
        call triangle_half(eta, out(:, 1), out(:, 2), out(:, 3), out(:, 4), regime)
        out(:, 5) = real(regime, dp)
    case (4)
        out(:, 1) = spike_velocity_ratio(eta)
    case default
        out(:, 1) = full_cycle_peak_regression(eta, out(:, 1))
    end select
end subroutine sp_limit_form

!> A block on an incline in SI; out(:, 1:12) = eta1, eta2, t_y1, t_m1, u_m1, t_y2, t_m2,
!> u_m2, u_res, v_m1, v_m2, 0.
subroutine sp_block(n, mu, ag, td, beta, full, slope, xi, sfac, static_reverse, along_plane, &
                    g, mode, out, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_sliding_closed, only: block_response, sliding_block_t
    implicit none
    integer, intent(in) :: n, full, static_reverse, along_plane
    real(dp), intent(in) :: mu(n), ag(n), td(n), beta(n), slope(n), xi(n), sfac(n), g
    integer, intent(out) :: mode(n)
    real(dp), intent(out) :: out(n, 11)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(sliding_block_t) :: r
    integer :: i
    errmsg = ''
    stat = SEISPULSE_SUCCESS
    do i = 1, n
        call block_response(mu(i), ag(i), td(i), beta(i), full /= 0, slope(i), xi(i), sfac(i), &
                            static_reverse /= 0, along_plane /= 0, g, r, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        mode(i) = r%mode
        out(i, :) = [r%eta1, r%eta2, r%t_y1, r%t_m1, r%u_m1, r%t_y2, r%t_m2, r%u_m2, r%u_res, &
                     r%v_m1, r%v_m2]
    end do
end subroutine sp_block

! ---------------------------------------------------------------------------------
! Normalization of sliding displacements (seispulse_sliding_norm)
! ---------------------------------------------------------------------------------

!> D_c = A^a V^b D^c t^d per element.
subroutine sp_characteristic_length(n, a, b, c, d, ag, vg, dg, td, dc, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_sliding_norm, only: characteristic_length
    implicit none
    integer, intent(in) :: n
    real(dp), intent(in) :: a(n), b(n), c(n), d(n), ag(n), vg(n), dg(n), td(n)
    real(dp), intent(out) :: dc(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    integer :: i
    errmsg = ''
    stat = SEISPULSE_SUCCESS
    do i = 1, n
        call characteristic_length(a(i), b(i), c(i), d(i), ag(i), vg(i), dg(i), td(i), dc(i), &
                                   stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
    end do
end subroutine sp_characteristic_length

!> The six lengths of Eq. 1.28 per element.
subroutine sp_basic_lengths(n, ag, vg, dg, td, lengths, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_sliding_norm, only: basic_lengths
    implicit none
    integer, intent(in) :: n
    real(dp), intent(in) :: ag(n), vg(n), dg(n), td(n)
    real(dp), intent(out) :: lengths(n, 6)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    integer :: i
    errmsg = ''
    stat = SEISPULSE_SUCCESS
    do i = 1, n
        call basic_lengths(ag(i), vg(i), dg(i), td(i), lengths(i, :), stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
    end do
end subroutine sp_basic_lengths

!> Exponents (a, b, c, d) of every cell of Table 1.2 `table` for the given row and
!> column values.
subroutine sp_table_1_2(table, nr, rows, nc, cols, exps, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_sliding_norm, only: table_1_2_exponents
    implicit none
    character(len=*), intent(in) :: table
    integer, intent(in) :: nr, nc
    real(dp), intent(in) :: rows(nr), cols(nc)
    real(dp), intent(out) :: exps(nr, nc, 4)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    integer :: i, j
    errmsg = ''
    stat = SEISPULSE_SUCCESS
    exps = 0.0_dp
    do j = 1, nc
        do i = 1, nr
            call table_1_2_exponents(table, rows(i), cols(j), exps(i, j, 1), exps(i, j, 2), &
                                     exps(i, j, 3), exps(i, j, 4), stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
        end do
    end do
end subroutine sp_table_1_2

!> Table 1.3 per beta.
subroutine sp_table_1_3(n, beta, full, ratios, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_sliding_norm, only: table_1_3
    implicit none
    integer, intent(in) :: n, full
    real(dp), intent(in) :: beta(n)
    real(dp), intent(out) :: ratios(n, 6)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    integer :: i
    errmsg = ''
    stat = SEISPULSE_SUCCESS
    do i = 1, n
        call table_1_3(beta(i), full /= 0, ratios(i, :), stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
    end do
end subroutine sp_table_1_3

! ---------------------------------------------------------------------------------
! Stick-slip integrator (seispulse_sliding_sim)
! ---------------------------------------------------------------------------------

!> One run under a pulse (kind > 0, params packed as in pulse_from_params) or a record
!> (kind = 0: accel(nrec), dt). slides(nmax, 8) = direction, t_start, t_stop, u_start,
!> u_stop, w_peak, t_peak, from_slip for the first min(nslides, nmax) slides; summary =
!> u_final, u_max, u_min, t_end; u, w at the times tg when ngrid > 0.
subroutine sp_stickslip(kind, params, nrec, accel, dt, ay_fwd, ay_rev, sfac, static_all, &
                        ngrid, tg, ug, wg, nmax, slides, nslides, summary, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_pulses, only: pulse_from_params
    use seispulse_sliding_sim, only: friction_t, stickslip_result_t, stickslip_pulse, &
                                   stickslip_record
    implicit none
    integer, intent(in) :: kind, nrec, static_all, ngrid, nmax
    real(dp), intent(in) :: params(9), accel(nrec), dt, ay_fwd, ay_rev, sfac, tg(ngrid)
    real(dp), intent(out) :: ug(ngrid), wg(ngrid), slides(nmax, 8), summary(4)
    integer, intent(out) :: nslides, stat
    character(len=256), intent(out) :: errmsg
    type(friction_t) :: fr
    type(stickslip_result_t) :: res
    integer :: i
    errmsg = ''
    slides = 0.0_dp
    summary = 0.0_dp
    ug = 0.0_dp
    wg = 0.0_dp
    nslides = 0
    fr = friction_t(ay_fwd=ay_fwd, ay_rev=ay_rev, static_factor=sfac, static_all=static_all /= 0)
    if (kind > 0) then
        if (ngrid > 0) then
            call stickslip_pulse(pulse_from_params(kind, params), fr, res, stat, errmsg, tg, ug, wg)
        else
            call stickslip_pulse(pulse_from_params(kind, params), fr, res, stat, errmsg)
        end if
    else
        if (ngrid > 0) then
            call stickslip_record(accel, dt, fr, res, stat, errmsg, tg, ug, wg)
        else
            call stickslip_record(accel, dt, fr, res, stat, errmsg)
        end if
    end if
    if (stat /= SEISPULSE_SUCCESS) return
    nslides = size(res%slides)
    do i = 1, min(nslides, nmax)
        associate (s => res%slides(i))
            slides(i, :) = [real(s%direction, dp), s%t_start, s%t_stop, s%u_start, s%u_stop, &
                            s%w_peak, s%t_peak, merge(1.0_dp, 0.0_dp, s%from_slip)]
        end associate
    end do
    summary = [res%u_final, res%u_max, res%u_min, res%t_end]
end subroutine sp_stickslip

! ---------------------------------------------------------------------------------
! Rocking blocks: linearized closed forms (seispulse_rocking_closed)
! ---------------------------------------------------------------------------------

!> Everything of the first excursion per case: region, tau_up, tau_c, tau_m, psi_max, tau_i.
subroutine sp_rocking_summary(n, f, eta, beta, region, out, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_rocking_closed, only: rocking_summary
    implicit none
    integer, intent(in) :: n
    real(dp), intent(in) :: f(n), eta(n), beta(n)
    integer, intent(out) :: region(n)
    real(dp), intent(out) :: out(n, 5)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    integer :: i
    errmsg = ''
    stat = SEISPULSE_SUCCESS
    do i = 1, n
        call rocking_summary(f(i), eta(i), beta(i), region(i), out(i, 1), out(i, 2), out(i, 3), &
                             out(i, 4), out(i, 5), stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
    end do
end subroutine sp_rocking_summary

!> Region and theta_max/alpha per case (the fast path of classify and max_rotation).
subroutine sp_rocking_extremes(n, f, eta, beta, region, psi_max, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_rocking_closed, only: rocking_extremes
    implicit none
    integer, intent(in) :: n
    real(dp), intent(in) :: f(n), eta(n), beta(n)
    integer, intent(out) :: region(n)
    real(dp), intent(out) :: psi_max(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    integer :: i
    errmsg = ''
    stat = SEISPULSE_SUCCESS
    do i = 1, n
        call rocking_extremes(f(i), eta(i), beta(i), region(i), psi_max(i), stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
    end do
end subroutine sp_rocking_extremes

!> psi and dpsi of the first excursion at the times tau (one f, eta, beta per point).
subroutine sp_rocking_response(n, tau, f, eta, beta, psi, dpsi, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_rocking_closed, only: rocking_response
    implicit none
    integer, intent(in) :: n
    real(dp), intent(in) :: tau(n), f(n), eta(n), beta(n)
    real(dp), intent(out) :: psi(n), dpsi(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    integer :: i
    errmsg = ''
    stat = SEISPULSE_SUCCESS
    do i = 1, n
        call rocking_response(tau(i), f(i), eta(i), beta(i), psi(i), dpsi(i), stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
    end do
end subroutine sp_rocking_response

!> Boundaries in the (f, eta) plane and their inverses, per element. which: 1 uplift time
!> (x = eta), 2 stability wall (x = f), 3 its inverse (x = eta), 4 overturn boundary at the
!> end (x = f), 5 at mid-pulse (x = f), 6/7 their inverses (x = eta), 8 S1/S2 boundary (x = f).
subroutine sp_rocking_curve(n, which, x, beta, y, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_rocking_closed, only: uplift_time, stability_wall, stability_wall_inverse, &
                                 overturn_boundary, overturn_boundary_inverse, s1_s2_boundary
    implicit none
    integer, intent(in) :: n, which
    real(dp), intent(in) :: x(n), beta(n)
    real(dp), intent(out) :: y(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    integer :: i
    errmsg = ''
    stat = SEISPULSE_SUCCESS
    do i = 1, n
        select case (which)
        case (1)
            call uplift_time(x(i), beta(i), y(i), stat, errmsg)
        case (2)
            call stability_wall(x(i), beta(i), y(i), stat, errmsg)
        case (3)
            call stability_wall_inverse(x(i), beta(i), y(i), stat, errmsg)
        case (4)
            call overturn_boundary(x(i), beta(i), .true., y(i), stat, errmsg)
        case (5)
            call overturn_boundary(x(i), beta(i), .false., y(i), stat, errmsg)
        case (6)
            call overturn_boundary_inverse(x(i), beta(i), .true., y(i), stat, errmsg)
        case (7)
            call overturn_boundary_inverse(x(i), beta(i), .false., y(i), stat, errmsg)
        case default
            call s1_s2_boundary(x(i), beta(i), y(i), stat, errmsg)
        end select
        if (stat /= SEISPULSE_SUCCESS) return
    end do
end subroutine sp_rocking_curve

!> Normalized rectangle forms (2.27, corrected 2.30, corrected 2.35); 0 < fbar < 1, 0 < eta < 1.
subroutine sp_rocking_rect_normalized(n, fbar, eta, out)
    use seispulse_kinds, only: dp
    use seispulse_rocking_closed, only: rect_time_of_max_normalized, rect_max_rotation_normalized, &
                                 rect_impact_time_normalized
    implicit none
    integer, intent(in) :: n
    real(dp), intent(in) :: fbar(n), eta(n)
    real(dp), intent(out) :: out(n, 3)
    out(:, 1) = rect_time_of_max_normalized(fbar, eta)
    out(:, 2) = rect_max_rotation_normalized(fbar, eta)
    out(:, 3) = rect_impact_time_normalized(fbar, eta)
end subroutine sp_rocking_rect_normalized

! ---------------------------------------------------------------------------------
! Rocking blocks: nonlinear integrator and maps (seispulse_rocking_sim)
! ---------------------------------------------------------------------------------

!> Block properties: which = 1 rectangle (x = b, y = h), 2 symmetric body (x = R,
!> y = alpha, z = I_o/(m R^2)); out = alpha, p, e, R.
subroutine sp_rocking_block(which, x, y, z, g, out, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_rocking_sim, only: rocking_block_t, rectangular_block, symmetric_block
    implicit none
    integer, intent(in) :: which
    real(dp), intent(in) :: x, y, z, g
    real(dp), intent(out) :: out(4)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(rocking_block_t) :: blk
    errmsg = ''
    out = 0.0_dp
    if (which == 1) then
        call rectangular_block(x, y, g, blk, stat, errmsg)
        out(4) = hypot(x, y)
    else
        call symmetric_block(x, y, z, g, blk, stat, errmsg)
        out(4) = x
    end if
    out(1:3) = [blk%alpha, blk%p, blk%e]
end subroutine sp_rocking_block

!> One run under a pulse (kind > 0, params packed as in pulse_from_params) or a record
!> (kind = 0: accel(nrec) in units of g (m/s^2), dt; g is unused for a pulse). opts = t_max (<= 0: none), theta0, omega0, rtol (<= 0:
!> the default).
!> res = t_uplift, t_overturn, theta_max, theta_min, t_end, n_steps; impacts: the first
!> min(n_imp, nmax) impact times.
subroutine sp_rock(kind, params, nrec, accel, dt, g, blkv, linearized, opts, ngrid, tg, thg, &
                   omg, nmax, impacts, n_imp, outcome, res, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_pulses, only: pulse_from_params
    use seispulse_rocking_sim, only: rocking_block_t, rocking_run_t, rock_pulse, rock_record
    implicit none
    integer, intent(in) :: kind, nrec, linearized, ngrid, nmax
    real(dp), intent(in) :: params(9), accel(nrec), dt, g, blkv(4), opts(4), tg(ngrid)
    real(dp), intent(out) :: thg(ngrid), omg(ngrid), impacts(nmax), res(6)
    integer, intent(out) :: n_imp, outcome, stat
    character(len=256), intent(out) :: errmsg
    type(rocking_block_t) :: blk
    type(rocking_run_t) :: run
    real(dp) :: t_max, rtol
    errmsg = ''
    thg = 0.0_dp
    omg = 0.0_dp
    impacts = 0.0_dp
    res = 0.0_dp
    n_imp = 0
    outcome = 0
    blk = rocking_block_t(alpha=blkv(1), p=blkv(2), e=blkv(3), g=blkv(4), &
                          linearized=linearized /= 0)
    t_max = huge(1.0_dp)
    if (opts(1) > 0.0_dp) t_max = opts(1)
    rtol = 1.0e-12_dp
    if (opts(4) > 0.0_dp) rtol = opts(4)
    if (kind > 0) then
        if (ngrid > 0) then
            call rock_pulse(blk, pulse_from_params(kind, params), run, stat, errmsg, tg, thg, &
                            omg, t_max=t_max, theta0=opts(2), omega0=opts(3), rtol=rtol)
        else
            call rock_pulse(blk, pulse_from_params(kind, params), run, stat, errmsg, &
                            t_max=t_max, theta0=opts(2), omega0=opts(3), rtol=rtol)
        end if
    else
        if (ngrid > 0) then
            call rock_record(blk, accel, dt, g, run, stat, errmsg, tg, thg, omg, t_max=t_max, &
                             theta0=opts(2), omega0=opts(3), rtol=rtol)
        else
            call rock_record(blk, accel, dt, g, run, stat, errmsg, t_max=t_max, &
                             theta0=opts(2), omega0=opts(3), rtol=rtol)
        end if
    end if
    if (stat /= SEISPULSE_SUCCESS) return
    outcome = run%outcome
    n_imp = run%n_impacts
    if (n_imp > 0) impacts(1:min(n_imp, nmax)) = run%t_impacts(1:min(n_imp, nmax))
    res = [run%t_uplift, run%t_overturn, run%theta_max, run%theta_min, run%t_end, &
           real(run%n_steps, dp)]
end subroutine sp_rock

!> Overturning map of a pulse family (template params packed as in pulse_from_params).
subroutine sp_overturning_map(alpha, e, kind, params, linearized, nf, freq, na, amp, classes, &
                              stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_pulses, only: pulse_from_params
    use seispulse_rocking_sim, only: overturning_map
    implicit none
    integer, intent(in) :: kind, linearized, nf, na
    real(dp), intent(in) :: alpha, e, params(9), freq(nf), amp(na)
    integer, intent(out) :: classes(na, nf)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call overturning_map(alpha, e, kind, freq, amp, classes, stat, errmsg, &
                         linearized=linearized /= 0, template=pulse_from_params(kind, params))
end subroutine sp_overturning_map

! ---------------------------------------------------------------------------------
! Newmark rigid-block sliding on records (seispulse_newmark)
! ---------------------------------------------------------------------------------

!> One analysis with histories and sliding intervals. nh = n for histories, else 1;
!> the first min(nslides, nmax) intervals are returned (the caller asks again with a
!> larger nmax when nslides > nmax). summary = max_disp, final_disp, u_max, u_min,
!> max_vel, t_end.
subroutine sp_newmark_rigid(n, accel, dt, mode, ky, ky_up, k_down, k_up, method, g, nh, &
                            u_hist, w_hist, nmax, slides, nslides, summary, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_newmark, only: newmark_block_t, newmark_result_t, newmark_rigid
    implicit none
    integer, intent(in) :: n, mode, method, nh, nmax
    real(dp), intent(in) :: accel(n), dt, ky, ky_up, k_down, k_up, g
    real(dp), intent(out) :: u_hist(nh), w_hist(nh), slides(nmax, 8), summary(6)
    integer, intent(out) :: nslides, stat
    character(len=256), intent(out) :: errmsg
    type(newmark_result_t) :: res
    integer :: i
    errmsg = ''
    u_hist = 0.0_dp
    w_hist = 0.0_dp
    slides = 0.0_dp
    summary = 0.0_dp
    nslides = 0
    if (nh == n) then
        call newmark_rigid(accel, dt, newmark_block_t(mode, ky, ky_up, k_down, k_up), method, g, &
                           res, stat, errmsg, u_hist, w_hist)
    else
        call newmark_rigid(accel, dt, newmark_block_t(mode, ky, ky_up, k_down, k_up), method, g, &
                           res, stat, errmsg)
    end if
    if (stat /= SEISPULSE_SUCCESS) return
    summary = [res%max_disp, res%final_disp, res%u_max, res%u_min, res%max_vel, res%t_end]
    nslides = size(res%slides)
    do i = 1, min(nslides, nmax)
        associate (s => res%slides(i))
            slides(i, :) = [real(s%direction, dp), s%t_start, s%t_stop, s%u_start, s%u_stop, &
                            s%w_peak, s%t_peak, merge(1.0_dp, 0.0_dp, s%from_slip)]
        end associate
    end do
end subroutine sp_newmark_rigid

!> Summaries for many blocks on one record (ky, ky_up, k_down, k_up of length nk).
subroutine sp_newmark_rigid_many(n, accel, dt, mode, nk, ky, ky_up, k_down, k_up, method, g, &
                                 summary, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_newmark, only: newmark_block_t, newmark_result_t, newmark_rigid
    implicit none
    integer, intent(in) :: n, mode, nk, method
    real(dp), intent(in) :: accel(n), dt, ky(nk), ky_up(nk), k_down(nk), k_up(nk), g
    real(dp), intent(out) :: summary(nk, 6)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(newmark_result_t) :: res
    integer :: i
    errmsg = ''
    summary = 0.0_dp
    stat = SEISPULSE_SUCCESS
    do i = 1, nk
        call newmark_rigid(accel, dt, newmark_block_t(mode, ky(i), ky_up(i), k_down(i), k_up(i)), &
                           method, g, res, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        summary(i, :) = [res%max_disp, res%final_disp, res%u_max, res%u_min, res%max_vel, &
                         res%t_end]
    end do
end subroutine sp_newmark_rigid_many

!> Yields and along-plane factors of a block on an incline (newmark_incline).
subroutine sp_newmark_incline(mu, slope_deg, xi_deg, along_plane, out, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_newmark, only: newmark_block_t, newmark_incline
    implicit none
    real(dp), intent(in) :: mu, slope_deg, xi_deg
    integer, intent(in) :: along_plane
    real(dp), intent(out) :: out(4)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(newmark_block_t) :: blk
    errmsg = ''
    call newmark_incline(mu, slope_deg, xi_deg, along_plane /= 0, blk, stat, errmsg)
    out = [blk%ky, blk%ky_up, blk%k_down, blk%k_up]
end subroutine sp_newmark_incline
