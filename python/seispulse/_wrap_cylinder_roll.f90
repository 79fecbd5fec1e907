! f2py thin layer of seispulse_cylinder_roll: plain subroutines, explicit-shape arrays,
! inline !f2py lines (gen_binding.py reads them). No numerics here.

!> One run of rocking with rolling (doc/rolling.md). The body crosses the layer as in
!> _wrap_cylinder.f90 (shape code, r, h, mass, g, r_inner, j_o, has_j_axis, j_axis) and is
!> rebuilt by make_body. Excitation: kind > 0 a pulse (params as pulse_from_params, SI)
!> along `direction` (rad); kind = 0 a two-component record accel_x, accel_y (nrec samples
!> in units of g_rec m/s^2, step dt); kind < 0 free motion. t_max only when has_t_max /= 0.
!> hist(ROLL_NOUT, ngrid) at tg; the n_imp impact times are held for sp_fetch_impacts
!> (sp_runs_held, _wrap.f90: the run is never repeated to fetch them).
subroutine sp_cylinder_roll(shape, r, h, mass, g, r_inner, j_o, has_j_axis, j_axis, e, kind, &
                            params, direction, nrec, accel_x, accel_y, dt, g_rec, theta0, psi0, &
                            spin0, theta_rate0, psi_rate0, spin_rate0, has_t_max, t_max, rtol, &
                            ngrid, tg, hist, n_imp, n_floor, outcome, t_uplift, &
                            theta_max, friction_max, t_lift_off, energy_drift, t_end, n_steps, &
                            stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_pulses, only: pulse_t, pulse_from_params, PULSE_NPARAM
    use seispulse_cylinder, only: rocking_body_t
    use seispulse_cylinder_roll, only: cylinder_roll, roll_run_t, ROLL_NOUT
    use sp_cylinder_body, only: make_body
    use sp_runs_held, only: held_impacts
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: nrec, ngrid
    integer, intent(in) :: shape, has_j_axis, kind, nrec, has_t_max, ngrid
    real(dp), intent(in) :: r, h, mass, g, r_inner, j_o, j_axis, e, params(PULSE_NPARAM)
    real(dp), intent(in) :: direction, accel_x(nrec), accel_y(nrec), dt, g_rec
    real(dp), intent(in) :: theta0, psi0, spin0, theta_rate0, psi_rate0, spin_rate0, t_max, rtol
    real(dp), intent(in) :: tg(ngrid)
    real(dp), intent(out) :: hist(ROLL_NOUT, ngrid)
    integer, intent(out) :: n_imp, n_floor, outcome, n_steps, stat
    real(dp), intent(out) :: t_uplift, theta_max, friction_max, t_lift_off, energy_drift, t_end
    character(len=256), intent(out) :: errmsg
    type(rocking_body_t) :: body
    type(roll_run_t) :: run
    ! optional arguments not given are unallocated allocatables: absent (F2008 12.5.2.12)
    type(pulse_t), allocatable :: pulse_opt
    real(dp), allocatable :: ax_opt(:), ay_opt(:), dt_opt, g_rec_opt, t_max_opt
    errmsg = ''
    hist = 0.0_dp
    if (allocated(held_impacts)) deallocate(held_impacts)
    n_imp = 0
    n_floor = 0
    outcome = 0
    n_steps = 0
    t_uplift = 0.0_dp
    theta_max = 0.0_dp
    friction_max = 0.0_dp
    t_lift_off = 0.0_dp
    energy_drift = 0.0_dp
    t_end = 0.0_dp
    call make_body(shape, r, h, mass, g, r_inner, j_o, has_j_axis, j_axis, body, stat, errmsg)
    if (stat /= SEISPULSE_SUCCESS) return
    if (kind > 0) then
        allocate(pulse_opt, source=pulse_from_params(kind, params))
    else if (kind == 0) then
        allocate(ax_opt, source=accel_x)
        allocate(ay_opt, source=accel_y)
        allocate(dt_opt, source=dt)
        allocate(g_rec_opt, source=g_rec)
    end if
    if (has_t_max /= 0) allocate(t_max_opt, source=t_max)
    call cylinder_roll(body, tg, hist, run, stat, errmsg, theta0, psi0, spin0, theta_rate0, &
                       psi_rate0, spin_rate0, pulse=pulse_opt, direction=direction, &
                       accel_x=ax_opt, accel_y=ay_opt, dt=dt_opt, g_rec=g_rec_opt, e=e, &
                       t_max=t_max_opt, rtol=rtol)
    if (stat /= SEISPULSE_SUCCESS) return
    n_imp = run%n_impacts
    if (n_imp > 0) allocate(held_impacts, source=run%t_impacts(1:n_imp))
    n_floor = run%n_floor
    outcome = run%outcome
    t_uplift = run%t_uplift
    theta_max = run%theta_max
    friction_max = run%friction_max
    t_lift_off = run%t_lift_off
    energy_drift = run%energy_drift
    t_end = run%t_end
    n_steps = run%n_steps
end subroutine sp_cylinder_roll
