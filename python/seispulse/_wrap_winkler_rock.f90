! Thin layer of seispulse_winkler_rock (doc/winkler.md "Dynamics": planar rocking on
! tensionless Winkler springs and dashpots) for seispulse.winkler. A model crosses the layer
! as the numbers that define it: the body as in _wrap_cylinder.f90 (shape code, r, h, mass,
! g, r_inner, j_o, has_j_axis, j_axis), the soil k (N/m^3), the half-length alpha (m, a
! block), k_method (K_*) and reading (AXIS_*, the shape factor of a varying k), and either
! the dashpot c (N s/m^3, has_c /= 0) or xi with damping_ref (DAMP_*). Each wrapper
! rebuilds it with winkler_model: every derived number comes from the library. No numerics
! here.

!> The model of a wrapper's arguments, and the impacts of the last run held for
!> sp_wk_fetch_impacts (module blocks are helpers, not seen by Python).
module sp_winkler_model
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_cylinder, only: rocking_body_t, BODY_BLOCK
    use seispulse_winkler_rock, only: winkler_model_t, winkler_model
    use sp_cylinder_body, only: make_body
    implicit none
    private
    public :: make_model, held_wk_impacts

    !> impact times (s), peak normal force (N) and peak foundation moment (N m) of the
    !> impacts of the last run, one row each
    real(dp), allocatable, save :: held_wk_impacts(:, :)

contains

    !> make_body, then winkler_model with c (has_c /= 0) or xi and damping_ref (has_xi /= 0);
    !> alpha is passed for a block only. Optional arguments not given are unallocated
    !> allocatables: absent (F2008 12.5.2.12).
    subroutine make_model(shape, r, h, mass, g, r_inner, j_o, has_j_axis, j_axis, k, alpha, &
                          k_method, reading, has_xi, xi, damping_ref, has_c, c, model, stat, &
                          errmsg)
        integer, intent(in) :: shape, has_j_axis, k_method, reading, has_xi, damping_ref, has_c
        real(dp), intent(in) :: r, h, mass, g, r_inner, j_o, j_axis, k, alpha, xi, c
        type(winkler_model_t), intent(out) :: model
        integer, intent(out) :: stat
        character(len=*), intent(inout) :: errmsg
        type(rocking_body_t) :: body
        real(dp), allocatable :: xi_opt, c_opt, alpha_opt
        call make_body(shape, r, h, mass, g, r_inner, j_o, has_j_axis, j_axis, body, stat, &
                       errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (has_xi /= 0) allocate(xi_opt, source=xi)
        if (has_c /= 0) allocate(c_opt, source=c)
        if (shape == BODY_BLOCK) allocate(alpha_opt, source=alpha)
        call winkler_model(body, k, model, stat, errmsg, alpha=alpha_opt, k_method=k_method, &
                           xi=xi_opt, damping_ref=damping_ref, c=c_opt, reading=reading)
    end subroutine make_model

end module sp_winkler_model

!> A Winkler rocking model (see the header): its footing (FOOTING_*), dashpot c (N s/m^3)
!> and static overturning angle (rad).
subroutine sp_wk_model(shape, r, h, mass, g, r_inner, j_o, has_j_axis, j_axis, k, alpha, &
                       k_method, reading, has_xi, xi, damping_ref, has_c, c, footing, c_out, &
                       theta_overturn, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_winkler_rock, only: winkler_model_t
    use sp_winkler_model, only: make_model
    implicit none
    !f2py threadsafe
    integer, intent(in) :: shape, has_j_axis, k_method, reading, has_xi, damping_ref, has_c
    real(dp), intent(in) :: r, h, mass, g, r_inner, j_o, j_axis, k, alpha, xi, c
    integer, intent(out) :: footing
    real(dp), intent(out) :: c_out, theta_overturn
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(winkler_model_t) :: model
    errmsg = ''
    footing = 0
    c_out = 0.0_dp
    theta_overturn = 0.0_dp
    call make_model(shape, r, h, mass, g, r_inner, j_o, has_j_axis, j_axis, k, alpha, &
                    k_method, reading, has_xi, xi, damping_ref, has_c, c, model, stat, errmsg)
    if (stat /= SEISPULSE_SUCCESS) return
    footing = model%footing
    c_out = model%c
    theta_overturn = model%theta_overturn
end subroutine sp_wk_model

!> One run of a Winkler rocking model (given c). Excitation: kind > 0 a pulse (params as
!> pulse_from_params, SI); kind = 0 a record accel (nrec samples in units of g_rec m/s^2,
!> step dt s); kind < 0 free motion. v0 (m) only when has_v0 /= 0 (else the static
!> settlement), theta0 (rad), the rates (m/s, rad/s); t_max (s) when has_t_max /= 0, rtol
!> when has_rtol /= 0. hist(WR_NOUT, ngrid) at tg (s); summary(9) = theta_max (rad),
!> t_uplift, t_lift_off, t_touch_down, t_overturn (s), normal_max (N), energy_error (-),
!> t_end, t_safe (s); the n_imp impacts are held for sp_wk_fetch_impacts.
subroutine sp_wk_rock(shape, r, h, mass, g, r_inner, j_o, has_j_axis, j_axis, k, alpha, &
                      k_method, reading, c, kind, params, nrec, accel, dt, g_rec, has_v0, v0, &
                      theta0, v_rate0, theta_rate0, has_t_max, t_max, has_rtol, rtol, ngrid, tg, &
                      hist, outcome, n_imp, n_steps, summary, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_pulses, only: pulse_t, pulse_from_params, PULSE_NPARAM
    use seispulse_winkler_rock, only: winkler_model_t, winkler_run_t, winkler_rock, WR_NOUT, &
                                      DAMP_ROCKING
    use sp_winkler_model, only: make_model, held_wk_impacts
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: nrec, ngrid
    integer, intent(in) :: shape, has_j_axis, k_method, reading, kind, nrec, has_v0
    integer, intent(in) :: has_t_max, has_rtol, ngrid
    real(dp), intent(in) :: r, h, mass, g, r_inner, j_o, j_axis, k, alpha, c
    real(dp), intent(in) :: params(PULSE_NPARAM), accel(nrec), dt, g_rec, v0, theta0, v_rate0
    real(dp), intent(in) :: theta_rate0, t_max, rtol, tg(ngrid)
    real(dp), intent(out) :: hist(WR_NOUT, ngrid), summary(9)
    integer, intent(out) :: outcome, n_imp, n_steps, stat
    character(len=256), intent(out) :: errmsg
    type(winkler_model_t) :: model
    type(winkler_run_t) :: run
    ! optional arguments not given are unallocated allocatables: absent (F2008 12.5.2.12)
    type(pulse_t), allocatable :: pulse_opt
    real(dp), allocatable :: accel_opt(:), dt_opt, g_rec_opt, v0_opt, t_max_opt, rtol_opt
    errmsg = ''
    hist = 0.0_dp
    summary = 0.0_dp
    outcome = 0
    n_imp = 0
    n_steps = 0
    if (allocated(held_wk_impacts)) deallocate(held_wk_impacts)
    call make_model(shape, r, h, mass, g, r_inner, j_o, has_j_axis, j_axis, k, alpha, &
                    k_method, reading, 0, 0.0_dp, DAMP_ROCKING, 1, c, model, stat, errmsg)
    if (stat /= SEISPULSE_SUCCESS) return
    if (kind > 0) then
        allocate(pulse_opt, source=pulse_from_params(kind, params))
    else if (kind == 0) then
        allocate(accel_opt, source=accel)
        allocate(dt_opt, source=dt)
        allocate(g_rec_opt, source=g_rec)
    end if
    if (has_v0 /= 0) allocate(v0_opt, source=v0)
    if (has_t_max /= 0) allocate(t_max_opt, source=t_max)
    if (has_rtol /= 0) allocate(rtol_opt, source=rtol)
    call winkler_rock(model, tg, hist, run, stat, errmsg, pulse=pulse_opt, accel=accel_opt, &
                      dt=dt_opt, g_rec=g_rec_opt, v0=v0_opt, theta0=theta0, v_rate0=v_rate0, &
                      theta_rate0=theta_rate0, t_max=t_max_opt, rtol=rtol_opt)
    if (stat /= SEISPULSE_SUCCESS) return
    outcome = run%outcome
    n_imp = run%n_impacts
    n_steps = run%n_steps
    summary = [run%theta_max, run%t_uplift, run%t_lift_off, run%t_touch_down, run%t_overturn, &
               run%normal_max, run%energy_error, run%t_end, run%t_safe]
    allocate(held_wk_impacts(n_imp, 3))
    if (n_imp > 0) then
        held_wk_impacts(:, 1) = run%t_impacts(1:n_imp)
        held_wk_impacts(:, 2) = run%impact_normal_peak(1:n_imp)
        held_wk_impacts(:, 3) = run%impact_moment_peak(1:n_imp)
    end if
end subroutine sp_wk_rock

!> The n impacts held by the last sp_wk_rock: time (s), peak normal force (N), peak
!> foundation moment (N m) per row; released after the call.
subroutine sp_wk_fetch_impacts(n, impacts)
    use seispulse_kinds, only: dp
    use sp_winkler_model, only: held_wk_impacts
    implicit none
    !f2py threadsafe
    integer, intent(in) :: n
    real(dp), intent(out) :: impacts(n, 3)
    impacts = 0.0_dp
    if (.not. allocated(held_wk_impacts)) return
    if (size(held_wk_impacts, 1) == n) impacts = held_wk_impacts
    deallocate(held_wk_impacts)
end subroutine sp_wk_fetch_impacts

!> Overturning map of a Winkler rocking model (given c) under a pulse family (template
!> packed as in pulse_from_params) on the axes MAP_AXES_*: classes(i, j) for y(i), x(j);
!> rtol when has_rtol /= 0.
subroutine sp_wk_map(shape, r, h, mass, g, r_inner, j_o, has_j_axis, j_axis, k, alpha, &
                     k_method, reading, c, kind, params, axes, has_rtol, rtol, nx, x, ny, y, &
                     classes, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_pulses, only: pulse_from_params, PULSE_NPARAM
    use seispulse_winkler_rock, only: winkler_model_t, winkler_overturning_map, DAMP_ROCKING
    use sp_winkler_model, only: make_model
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: nx, ny
    integer, intent(in) :: shape, has_j_axis, k_method, reading, kind, axes, has_rtol, nx, ny
    real(dp), intent(in) :: r, h, mass, g, r_inner, j_o, j_axis, k, alpha, c
    real(dp), intent(in) :: params(PULSE_NPARAM), rtol, x(nx), y(ny)
    integer, intent(out) :: classes(ny, nx)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(winkler_model_t) :: model
    real(dp), allocatable :: rtol_opt              ! unallocated: absent (F2008 12.5.2.12)
    errmsg = ''
    classes = -1
    call make_model(shape, r, h, mass, g, r_inner, j_o, has_j_axis, j_axis, k, alpha, &
                    k_method, reading, 0, 0.0_dp, DAMP_ROCKING, 1, c, model, stat, errmsg)
    if (stat /= SEISPULSE_SUCCESS) return
    if (has_rtol /= 0) allocate(rtol_opt, source=rtol)
    call winkler_overturning_map(model, kind, x, y, axes, classes, stat, errmsg, &
                                 template=pulse_from_params(kind, params), rtol=rtol_opt)
end subroutine sp_wk_map
