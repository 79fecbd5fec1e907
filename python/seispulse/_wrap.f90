!> Thin f2py layer: plain external subroutines with explicit-shape arrays, scalar
!> integer/double/fixed-length character arguments only, `stat` + `errmsg` out.
!> No numerics here: each routine translates its arguments and calls the library
!> (f2py cannot pass derived types, optionals or allocatables).
!> These sources are the only signatures: f2py reads them at build time (gen_binding.py);
!> `!f2py intent(hide)` lines hide the sizes f2py takes from the arrays, and .f2py_f2cmap
!> maps real(dp) to C double (checked by the build and test_binding_kinds.py).
!> Every routine has a `!f2py threadsafe` line: its C wrapper releases the GIL during the
!> Fortran call (the build checks it), so it must keep nothing between calls. The held
!> results (sp_runs_held below, sp_records_held, sp_winkler_model) are the exception: Python
!> makes each run + fetch pair under one lock (_core.HELD_LOCK, records._READ_LOCK).
!> Element-by-element loops over a scalar routine are not written here: one line each in
!> _wrap_loops.txt, from which gen_binding.py writes _wrap_loops.f90 at build time.

!> The sliding intervals of the last sp_stickslip or sp_newmark_rigid run and the impact
!> times of the last sp_rock run, kept until sp_fetch_slides / sp_fetch_impacts: the run
!> returns their number, the caller sizes the arrays from it, and no analysis runs twice.
!> The Python side makes both calls under one lock.
module sp_runs_held
    use seispulse_kinds, only: dp
    use seispulse_sliding_sim, only: slide_t
    implicit none
    private
    public :: held_slides, held_impacts

    type(slide_t), allocatable, save :: held_slides(:)  !! intervals of the last run
    real(dp), allocatable, save :: held_impacts(:)      !! impact times of the last run
end module sp_runs_held

!> Exponential pulse, dimensionless; beta has length 1 or n.
subroutine sp_exp_pulse(n, tau, nb, beta, full, a, v, d, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_pulses, only: exp_pulse
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n, nb
    integer, intent(in) :: n, nb, full
    real(dp), intent(in) :: tau(n), beta(nb)
    real(dp), intent(out) :: a(n), v(n), d(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call exp_pulse(tau, beta, full /= 0, a, v, d, stat, errmsg)
end subroutine sp_exp_pulse

! Hand-written (not in _wrap_loops.txt): one parameter row evaluates the whole t in one call.
!> Any pulse in SI units; params(np, PULSE_NPARAM) packed as in pulse_from_params,
!> np = 1 or n.
subroutine sp_pulse_eval(kind, n, t, np, params, a, v, d, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_pulses, only: pulse_t, pulse_eval, pulse_from_params, PULSE_NPARAM
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n, np
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

!> End time (s) of a pulse (pulse_end_time): the acceleration is zero for good after it;
!> +inf for the Ricker wavelet. The parameters are checked (pulse_validate).
subroutine sp_pulse_end_time(kind, params, t_end, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_pulses, only: pulse_t, pulse_end_time, pulse_from_params, pulse_validate, &
                                PULSE_NPARAM
    implicit none
    !f2py threadsafe
    integer, intent(in) :: kind
    real(dp), intent(in) :: params(PULSE_NPARAM)
    real(dp), intent(out) :: t_end
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(pulse_t) :: p
    errmsg = ''
    t_end = 0.0_dp
    p = pulse_from_params(kind, params)
    call pulse_validate(p, stat, errmsg)
    if (stat == SEISPULSE_SUCCESS) t_end = pulse_end_time(p)
end subroutine sp_pulse_end_time

!> Pulse kind code from its name.
subroutine sp_pulse_kind(name, kind, stat, errmsg)
    use seispulse_pulses, only: pulse_kind_from_name
    implicit none
    !f2py threadsafe
    character(len=*), intent(in) :: name
    integer, intent(out) :: kind, stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call pulse_kind_from_name(name, kind, stat, errmsg)
end subroutine sp_pulse_kind

! ---------------------------------------------------------------------------------
! Sliding block (seispulse_sliding_closed); every array has length n (broadcast in Python)
! ---------------------------------------------------------------------------------

!> Closed forms: which = 1 rectangle half (tau_m, um, um/dugm, vm), 2 rectangle full
!> (tau_m1, um1, tau_m2, um2, ures), 3 triangle half (tau_y, tau_m, um, vm, regime),
!> 4 spike (vm), 5 regression 1.30 (um/D_g; beta in out(:, 1) on entry). eta in (0, 1).
subroutine sp_limit_form(n, which, eta, out)
    use seispulse_kinds, only: dp
    use seispulse_sliding_closed, only: rectangle_half, rectangle_full, triangle_half, &
                                 spike_velocity_ratio, full_cycle_peak_regression
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    !f2py intent(in,out) :: out
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

! ---------------------------------------------------------------------------------
! Normalization of sliding displacements (seispulse_sliding_norm)
! ---------------------------------------------------------------------------------

! Hand-written (not in _wrap_loops.txt): a rows x cols table from two loops, not one.
!> Exponents (a, b, c, d) of every cell of Table 1.2 `table` for the given row and
!> column values.
subroutine sp_table_1_2(table, nr, rows, nc, cols, exps, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_sliding_norm, only: table_1_2_exponents
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: nr, nc
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

! ---------------------------------------------------------------------------------
! Stick-slip integrator (seispulse_sliding_sim)
! ---------------------------------------------------------------------------------

!> One run under a pulse (kind > 0, params packed as in pulse_from_params) or a record
!> (kind = 0: accel(nrec), dt); u, w at the times tg when ngrid > 0. The nslides slides
!> are kept for sp_fetch_slides.
subroutine sp_stickslip(kind, params, nrec, accel, dt, ay_fwd, ay_rev, sfac, static_all, &
                        ngrid, tg, ug, wg, nslides, u_final, u_max, u_min, t_end, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_pulses, only: pulse_from_params, PULSE_NPARAM
    use seispulse_sliding_sim, only: friction_t, stickslip_result_t, stickslip_pulse, &
                                   stickslip_record
    use sp_runs_held, only: held_slides
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: nrec, ngrid
    integer, intent(in) :: kind, nrec, static_all, ngrid
    real(dp), intent(in) :: params(PULSE_NPARAM), accel(nrec), dt, ay_fwd, ay_rev, sfac, &
                            tg(ngrid)
    real(dp), intent(out) :: ug(ngrid), wg(ngrid)
    real(dp), intent(out) :: u_final, u_max, u_min, t_end
    integer, intent(out) :: nslides, stat
    character(len=256), intent(out) :: errmsg
    type(friction_t) :: fr
    type(stickslip_result_t) :: res
    errmsg = ''
    if (allocated(held_slides)) deallocate(held_slides)
    u_final = 0.0_dp
    u_max = 0.0_dp
    u_min = 0.0_dp
    t_end = 0.0_dp
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
        ! accel and ay in the caller's units (any, the same for both): g = 1
        if (ngrid > 0) then
            call stickslip_record(accel, dt, fr, 1.0_dp, res, stat, errmsg, tg, ug, wg)
        else
            call stickslip_record(accel, dt, fr, 1.0_dp, res, stat, errmsg)
        end if
    end if
    if (stat /= SEISPULSE_SUCCESS) return
    nslides = size(res%slides)
    call move_alloc(res%slides, held_slides)
    u_final = res%u_final
    u_max = res%u_max
    u_min = res%u_min
    t_end = res%t_end
end subroutine sp_stickslip

! ---------------------------------------------------------------------------------
! Rocking blocks: linearized closed forms (seispulse_rocking_closed)
! ---------------------------------------------------------------------------------

!> Normalized rectangle forms (2.27, corrected 2.30, corrected 2.35); 0 < fbar < 1, 0 < eta < 1.
subroutine sp_rocking_rect_normalized(n, fbar, eta, out)
    use seispulse_kinds, only: dp
    use seispulse_rocking_closed, only: rect_time_of_max_normalized, rect_max_rotation_normalized, &
                                 rect_impact_time_normalized
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
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
!> y = alpha, z = I_o/(m R^2)).
subroutine sp_rocking_block(which, x, y, z, g, alpha, p, e, r, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_rocking_sim, only: rocking_block_t, rectangular_block, symmetric_block
    implicit none
    !f2py threadsafe
    integer, intent(in) :: which
    real(dp), intent(in) :: x, y, z, g
    real(dp), intent(out) :: alpha, p, e, r
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(rocking_block_t) :: blk
    errmsg = ''
    if (which == 1) then
        call rectangular_block(x, y, g, blk, stat, errmsg)
        r = hypot(x, y)
    else
        call symmetric_block(x, y, z, g, blk, stat, errmsg)
        r = x
    end if
    alpha = blk%alpha
    p = blk%p
    e = blk%e
end subroutine sp_rocking_block

!> One run under a pulse (kind > 0, params packed as in pulse_from_params) or a record
!> (kind = 0: accel(nrec) in m/s^2, handed to rock_record as a record in units of 1 m/s^2, so
!> that g * accel is accel bit for bit; dt); the block is alpha, p, e, g; t_max only when
!> has_t_max /= 0. Vertical ground acceleration: a_v = kv a_g under a pulse; under a record
!> accel_v(nrec) (m/s^2, as accel) when has_v /= 0.
!> The n_imp impact times are kept for sp_fetch_impacts.
subroutine sp_rock(kind, params, nrec, accel, dt, alpha, p, e, g, linearized, has_t_max, t_max, &
                   theta0, omega0, rtol, kv, has_v, accel_v, ngrid, tg, thg, omg, n_imp, outcome, &
                   t_uplift, t_overturn, theta_max, theta_min, t_end, n_steps, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_pulses, only: pulse_from_params, PULSE_NPARAM
    use seispulse_rocking_sim, only: rocking_block_t, rocking_run_t, rock_pulse, rock_record
    use sp_runs_held, only: held_impacts
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: nrec, ngrid
    integer, intent(in) :: kind, nrec, linearized, has_t_max, ngrid, has_v
    real(dp), intent(in) :: params(PULSE_NPARAM), accel(nrec), dt, alpha, p, e, g, t_max, &
                            theta0, omega0, rtol, tg(ngrid), kv, accel_v(nrec)
    real(dp), intent(out) :: thg(ngrid), omg(ngrid)
    real(dp), intent(out) :: t_uplift, t_overturn, theta_max, theta_min, t_end
    integer, intent(out) :: n_imp, outcome, n_steps, stat
    character(len=256), intent(out) :: errmsg
    type(rocking_block_t) :: blk
    type(rocking_run_t) :: run
    real(dp) :: t_lim
    real(dp), allocatable :: av(:)
    errmsg = ''
    thg = 0.0_dp
    omg = 0.0_dp
    if (allocated(held_impacts)) deallocate(held_impacts)
    t_uplift = 0.0_dp
    t_overturn = 0.0_dp
    theta_max = 0.0_dp
    theta_min = 0.0_dp
    t_end = 0.0_dp
    n_steps = 0
    n_imp = 0
    outcome = 0
    blk = rocking_block_t(alpha=alpha, p=p, e=e, g=g, linearized=linearized /= 0)
    t_lim = huge(1.0_dp)
    if (has_t_max /= 0) t_lim = t_max
    if (kind > 0) then
        if (ngrid > 0) then
            call rock_pulse(blk, pulse_from_params(kind, params), run, stat, errmsg, tg, thg, &
                            omg, t_max=t_lim, theta0=theta0, omega0=omega0, rtol=rtol, kv=kv)
        else
            call rock_pulse(blk, pulse_from_params(kind, params), run, stat, errmsg, &
                            t_max=t_lim, theta0=theta0, omega0=omega0, rtol=rtol, kv=kv)
        end if
    else
        ! without a vertical record av stays unallocated: absent (F2008 12.5.2.12)
        if (has_v /= 0) allocate(av, source=accel_v)
        if (ngrid > 0) then
            call rock_record(blk, accel, dt, 1.0_dp, run, stat, errmsg, tg, thg, omg, &
                             t_max=t_lim, theta0=theta0, omega0=omega0, rtol=rtol, accel_v=av)
        else
            call rock_record(blk, accel, dt, 1.0_dp, run, stat, errmsg, t_max=t_lim, &
                             theta0=theta0, omega0=omega0, rtol=rtol, accel_v=av)
        end if
    end if
    if (stat /= SEISPULSE_SUCCESS) return
    outcome = run%outcome
    n_imp = run%n_impacts
    if (n_imp > 0) allocate(held_impacts, source=run%t_impacts(1:n_imp))
    t_uplift = run%t_uplift
    t_overturn = run%t_overturn
    theta_max = run%theta_max
    theta_min = run%theta_min
    t_end = run%t_end
    n_steps = run%n_steps
end subroutine sp_rock

!> Overturning map of a pulse family (template params packed as in pulse_from_params);
!> a_v = kv a_g in every cell.
subroutine sp_overturning_map(alpha, e, kind, params, linearized, nf, freq, na, amp, kv, classes, &
                              stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_pulses, only: pulse_from_params, PULSE_NPARAM
    use seispulse_rocking_sim, only: overturning_map
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: nf, na
    integer, intent(in) :: kind, linearized, nf, na
    real(dp), intent(in) :: alpha, e, params(PULSE_NPARAM), freq(nf), amp(na), kv
    integer, intent(out) :: classes(na, nf)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call overturning_map(alpha, e, kind, freq, amp, classes, stat, errmsg, &
                         linearized=linearized /= 0, template=pulse_from_params(kind, params), &
                         kv=kv)
end subroutine sp_overturning_map

! ---------------------------------------------------------------------------------
! Newmark rigid-block sliding on records (seispulse_newmark)
! ---------------------------------------------------------------------------------

!> One analysis with histories and sliding intervals. nh = n for histories, else 1; the
!> nslides intervals are kept for sp_fetch_slides. table /= 0: the yield table ky_disp (m),
!> ky_values (g) instead of ky (mode down); else they are ignored (one dummy row).
subroutine sp_newmark_rigid(n, accel, dt, mode, ky, ky_up, k_down, k_up, method, g, nh, &
                            table, nt, ky_disp, ky_values, u_hist, w_hist, nslides, max_disp, &
                            final_disp, u_max, u_min, max_vel, t_end, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_newmark, only: newmark_block_t, newmark_result_t, newmark_rigid
    use sp_runs_held, only: held_slides
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n, nt
    integer, intent(in) :: n, mode, method, nh, table, nt
    real(dp), intent(in) :: accel(n), dt, ky, ky_up, k_down, k_up, g, ky_disp(nt), ky_values(nt)
    real(dp), intent(out) :: u_hist(nh), w_hist(nh)
    real(dp), intent(out) :: max_disp, final_disp, u_max, u_min, max_vel, t_end
    integer, intent(out) :: nslides, stat
    character(len=256), intent(out) :: errmsg
    type(newmark_result_t) :: res
    type(newmark_block_t) :: blk
    errmsg = ''
    if (allocated(held_slides)) deallocate(held_slides)
    u_hist = 0.0_dp
    w_hist = 0.0_dp
    max_disp = 0.0_dp
    final_disp = 0.0_dp
    u_max = 0.0_dp
    u_min = 0.0_dp
    max_vel = 0.0_dp
    t_end = 0.0_dp
    nslides = 0
    blk = newmark_block_t(mode, ky, ky_up, k_down, k_up)
    if (table /= 0) then
        allocate(blk%ky_disp, source=ky_disp)
        allocate(blk%ky_values, source=ky_values)
    end if
    if (nh == n) then
        call newmark_rigid(accel, dt, blk, method, g, res, stat, errmsg, u_hist, w_hist)
    else
        call newmark_rigid(accel, dt, blk, method, g, res, stat, errmsg)
    end if
    if (stat /= SEISPULSE_SUCCESS) return
    max_disp = res%max_disp
    final_disp = res%final_disp
    u_max = res%u_max
    u_min = res%u_min
    max_vel = res%max_vel
    t_end = res%t_end
    nslides = size(res%slides)
    call move_alloc(res%slides, held_slides)
end subroutine sp_newmark_rigid


! Hand-written (not in _wrap_loops.txt): each block runs the whole record accel(n).
!> Summaries for many blocks on one record (ky, ky_up, k_down, k_up of length nk).
subroutine sp_newmark_rigid_many(n, accel, dt, mode, nk, ky, ky_up, k_down, k_up, method, g, &
                                 max_disp, final_disp, u_max, u_min, max_vel, t_end, stat, &
                                 errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_newmark, only: newmark_block_t, newmark_result_t, newmark_rigid
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n, nk
    integer, intent(in) :: n, mode, nk, method
    real(dp), intent(in) :: accel(n), dt, ky(nk), ky_up(nk), k_down(nk), k_up(nk), g
    real(dp), intent(out) :: max_disp(nk), final_disp(nk), u_max(nk), u_min(nk), max_vel(nk), &
                             t_end(nk)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(newmark_result_t) :: res
    integer :: i
    errmsg = ''
    max_disp = 0.0_dp
    final_disp = 0.0_dp
    u_max = 0.0_dp
    u_min = 0.0_dp
    max_vel = 0.0_dp
    t_end = 0.0_dp
    stat = SEISPULSE_SUCCESS
    do i = 1, nk
        call newmark_rigid(accel, dt, newmark_block_t(mode, ky(i), ky_up(i), k_down(i), k_up(i)), &
                           method, g, res, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        max_disp(i) = res%max_disp
        final_disp(i) = res%final_disp
        u_max(i) = res%u_max
        u_min(i) = res%u_min
        max_vel(i) = res%max_vel
        t_end(i) = res%t_end
    end do
end subroutine sp_newmark_rigid_many

!> Yields and along-plane factors of a block on an incline (newmark_incline).
subroutine sp_newmark_incline(mu, slope_deg, xi_deg, along_plane, ky, ky_up, k_down, k_up, &
                              stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_newmark, only: newmark_block_t, newmark_incline
    implicit none
    !f2py threadsafe
    real(dp), intent(in) :: mu, slope_deg, xi_deg
    integer, intent(in) :: along_plane
    real(dp), intent(out) :: ky, ky_up, k_down, k_up
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(newmark_block_t) :: blk
    errmsg = ''
    call newmark_incline(mu, slope_deg, xi_deg, along_plane /= 0, blk, stat, errmsg)
    ky = blk%ky
    ky_up = blk%ky_up
    k_down = blk%k_down
    k_up = blk%k_up
end subroutine sp_newmark_incline

!> The n intervals kept by the last sp_stickslip or sp_newmark_rigid run (then freed):
!> direction +1/-1, times, displacements, peak velocity and its time, from_slip 0/1.
subroutine sp_fetch_slides(n, direction, t_start, t_stop, u_start, u_stop, w_peak, t_peak, &
                           from_slip)
    use seispulse_kinds, only: dp
    use sp_runs_held, only: held_slides
    implicit none
    !f2py threadsafe
    integer, intent(in) :: n
    integer, intent(out) :: direction(n), from_slip(n)
    real(dp), intent(out) :: t_start(n), t_stop(n), u_start(n), u_stop(n), w_peak(n), t_peak(n)
    integer :: i
    direction = 0
    from_slip = 0
    t_start = 0.0_dp
    t_stop = 0.0_dp
    u_start = 0.0_dp
    u_stop = 0.0_dp
    w_peak = 0.0_dp
    t_peak = 0.0_dp
    if (.not. allocated(held_slides)) return
    do i = 1, min(n, size(held_slides))
        direction(i) = held_slides(i)%direction
        t_start(i) = held_slides(i)%t_start
        t_stop(i) = held_slides(i)%t_stop
        u_start(i) = held_slides(i)%u_start
        u_stop(i) = held_slides(i)%u_stop
        w_peak(i) = held_slides(i)%w_peak
        t_peak(i) = held_slides(i)%t_peak
        from_slip(i) = merge(1, 0, held_slides(i)%from_slip)
    end do
    deallocate(held_slides)
end subroutine sp_fetch_slides

!> The n impact times kept by the last sp_rock run (then freed).
subroutine sp_fetch_impacts(n, times)
    use seispulse_kinds, only: dp
    use sp_runs_held, only: held_impacts
    implicit none
    !f2py threadsafe
    integer, intent(in) :: n
    real(dp), intent(out) :: times(n)
    times = 0.0_dp
    if (.not. allocated(held_impacts)) return
    times(1:min(n, size(held_impacts))) = held_impacts(1:min(n, size(held_impacts)))
    deallocate(held_impacts)
end subroutine sp_fetch_impacts
