!> Thin f2py layer of the flexible sliding masses (seispulse_flexible): plain external
!> subroutines, explicit-shape arrays, integer flags, `stat` + `errmsg` out, no numerics.

!> The call of sp_flexible with its optional table passed on (f2py does not see modules).
module sp_flexible_helpers
    use seispulse_kinds, only: dp
    use seispulse_flexible_model, only: flexible_mass_t, flexible_result_t
    use seispulse_flexible, only: flexible_decoupled, flexible_coupled
    implicit none
    private
    public :: sp_flexible_run
contains
    !> analysis 1 decoupled, 2 coupled; histories when want_hist.
    subroutine sp_flexible_run(analysis, accel, dt, ky, mass, method, g, mode, ky_up, want_hist, &
                               res, stat, errmsg, hea, u_modal, s_hist, sdot_hist, td, tv)
        integer, intent(in) :: analysis, method, mode
        real(dp), intent(in) :: accel(:), dt, ky, g, ky_up
        type(flexible_mass_t), intent(in) :: mass
        logical, intent(in) :: want_hist
        type(flexible_result_t), intent(out) :: res
        integer, intent(out) :: stat
        character(len=*), intent(inout) :: errmsg
        real(dp), intent(inout) :: hea(:), u_modal(:), s_hist(:), sdot_hist(:)
        real(dp), intent(in), optional :: td(:), tv(:)
        if (analysis == 2) then
            if (want_hist) then
                call flexible_coupled(accel, dt, ky, mass, method, g, res, stat, errmsg, td, tv, &
                                      hea, u_modal, s_hist, sdot_hist)
            else
                call flexible_coupled(accel, dt, ky, mass, method, g, res, stat, errmsg, td, tv)
            end if
        else
            if (want_hist) then
                call flexible_decoupled(accel, dt, ky, mass, method, g, res, stat, errmsg, mode, &
                                        ky_up, td, tv, hea, u_modal, s_hist, sdot_hist)
            else
                call flexible_decoupled(accel, dt, ky, mass, method, g, res, stat, errmsg, mode, &
                                        ky_up, td, tv)
            end if
        end if
    end subroutine sp_flexible_run
end module sp_flexible_helpers

!> One decoupled (analysis 1) or coupled (analysis 2) run. soil, method and mode are the
!> library's codes; a yield table (ky_disp, ky_values) when table = 1 (then ky is
!> ignored; else they are dummy arrays of size 1, not read); histories when nh = n
!> (else nh = 1 and they are left 0). On SEISPULSE_NO_CONVERGENCE the outputs hold the
!> last iteration's results.
subroutine sp_flexible(n, accel, dt, ky, analysis, height, vs, vs_base, damping, soil, &
                       ref_strain_pct, max_iter, method, g, mode, ky_up, table, nt, ky_disp, &
                       ky_values, nh, hea, u_modal, s_hist, sdot_hist, max_disp, final_disp, &
                       kmax, vs_final, damping_final, damping_radiation, period, iterations, &
                       converged, t_end, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_flexible_model, only: flexible_mass_t, flexible_result_t
    use sp_flexible_helpers, only: sp_flexible_run
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n, nt
    integer, intent(in) :: n, analysis, soil, max_iter, method, mode, table, nt, nh
    real(dp), intent(in) :: accel(n), dt, ky, height, vs, vs_base, damping, ref_strain_pct, g
    real(dp), intent(in) :: ky_up, ky_disp(nt), ky_values(nt)
    real(dp), intent(out) :: hea(nh), u_modal(nh), s_hist(nh), sdot_hist(nh)
    real(dp), intent(out) :: max_disp, final_disp, kmax, vs_final, damping_final, &
                             damping_radiation, period, t_end
    integer, intent(out) :: iterations, converged, stat
    character(len=256), intent(out) :: errmsg
    type(flexible_mass_t) :: mass
    type(flexible_result_t) :: res
    errmsg = ''
    hea = 0.0_dp
    u_modal = 0.0_dp
    s_hist = 0.0_dp
    sdot_hist = 0.0_dp
    mass = flexible_mass_t(height=height, vs=vs, vs_base=vs_base, damping=damping, soil=soil, &
                           ref_strain_pct=ref_strain_pct, max_iter=max_iter)
    if (table /= 0) then
        call sp_flexible_run(analysis, accel, dt, ky, mass, method, g, mode, ky_up, nh == n, res, &
                             stat, errmsg, hea, u_modal, s_hist, sdot_hist, ky_disp, ky_values)
    else
        call sp_flexible_run(analysis, accel, dt, ky, mass, method, g, mode, ky_up, nh == n, res, &
                             stat, errmsg, hea, u_modal, s_hist, sdot_hist)
    end if
    max_disp = res%max_disp
    final_disp = res%final_disp
    kmax = res%kmax
    vs_final = res%vs_final
    damping_final = res%damping_final
    damping_radiation = res%damping_radiation
    period = res%period
    iterations = res%iterations
    converged = merge(1, 0, res%converged)
    t_end = res%t_end
end subroutine sp_flexible
