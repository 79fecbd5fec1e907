! Thin layer of seispulse_winkler (doc/winkler.md: statics of a cylinder or a block on
! tensionless Winkler soil) for seispulse.winkler: plain subroutines, explicit-shape arrays,
! inline !f2py lines (gen_binding.py reads them). No numerics here. The element-by-element
! wrappers (moduli, stiffnesses, varying k) are entries of _wrap_loops.txt.

!> The scalars of a pushover result, zero when the call failed (module blocks are helpers
!> of the wrappers, not seen by Python).
module sp_winkler_results
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_winkler, only: winkler_pushover_t
    implicit none
    private
    public :: pushover_scalars

contains

    !> s(1:8) = theta_up, k0, max_force_over_weight, theta_at_max, max_moment,
    !> theta_at_max_moment, theta_overturn, theta_end of res (0 when stat /= 0).
    pure subroutine pushover_scalars(res, stat, s)
        type(winkler_pushover_t), intent(in) :: res
        integer, intent(in) :: stat
        real(dp), intent(out) :: s(8)
        s = 0.0_dp
        if (stat /= SEISPULSE_SUCCESS) return
        s = [res%theta_up, res%k0, res%max_force_over_weight, res%theta_at_max, &
             res%max_moment, res%theta_at_max_moment, res%theta_overturn, res%theta_end]
    end subroutine pushover_scalars

end module sp_winkler_results

!> Shape factor k_circle/k_square of the varying-k method for the reading AXIS_LONG or
!> AXIS_SHORT (-).
subroutine sp_wk_shape_factor(reading, factor, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_winkler, only: shape_factor
    implicit none
    !f2py threadsafe
    integer, intent(in) :: reading
    real(dp), intent(out) :: factor
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    factor = 0.0_dp
    call shape_factor(reading, factor, stat, errmsg)
end subroutine sp_wk_shape_factor

!> Universal small-angle curve of the constant-k footing (FOOTING_*) at x = theta/theta_up
!> >= 0 (elemental, no stat: x is checked by the caller): K_sec/K_0, M/(W r), b/(2 r), a/r.
subroutine sp_wk_master_curve(footing, n, x, k_ratio, m_ratio, b_ratio, a_ratio)
    use seispulse_kinds, only: dp
    use seispulse_winkler, only: winkler_master_curve
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: footing, n
    real(dp), intent(in) :: x(n)
    real(dp), intent(out) :: k_ratio(n), m_ratio(n), b_ratio(n), a_ratio(n)
    call winkler_master_curve(footing, x, k_ratio, m_ratio, b_ratio, a_ratio)
end subroutine sp_wk_master_curve

!> Winkler pushover of a circular base (radius r, m; centre of mass at h, m; weight, N;
!> full-contact k, N/m^3) on the tilts theta (rad): curve(n, WP_NCOL) in the columns WP_*;
!> scalars(8) as pushover_scalars (rad, N/m^3, -, rad, N m, rad, rad, rad). k_method K_*,
!> reading AXIS_* (the shape factor of varying k).
subroutine sp_wk_pushover(r, h, weight, k, k_method, reading, n, theta, curve, scalars, stat, &
                          errmsg)
    use seispulse_kinds, only: dp
    use seispulse_winkler, only: winkler_pushover, winkler_pushover_t, WP_NCOL
    use sp_winkler_results, only: pushover_scalars
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: k_method, reading, n
    real(dp), intent(in) :: r, h, weight, k, theta(n)
    real(dp), intent(out) :: curve(n, WP_NCOL), scalars(8)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(winkler_pushover_t) :: res
    errmsg = ''
    curve = 0.0_dp
    call winkler_pushover(r, h, weight, k, theta, curve, res, stat, errmsg, k_method=k_method, &
                          reading=reading)
    call pushover_scalars(res, stat, scalars)
end subroutine sp_wk_pushover

!> Winkler pushover of a rectangular base (half-width b along the rocking direction and
!> half-length alpha, m; h, m; weight, N; full-contact k, N/m^3) on the tilts theta (rad):
!> as sp_wk_pushover.
subroutine sp_wk_block_pushover(b, alpha, h, weight, k, k_method, n, theta, curve, scalars, &
                                stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_winkler, only: block_winkler_pushover, winkler_pushover_t, WP_NCOL
    use sp_winkler_results, only: pushover_scalars
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: k_method, n
    real(dp), intent(in) :: b, alpha, h, weight, k, theta(n)
    real(dp), intent(out) :: curve(n, WP_NCOL), scalars(8)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(winkler_pushover_t) :: res
    errmsg = ''
    curve = 0.0_dp
    call block_winkler_pushover(b, alpha, h, weight, k, theta, curve, res, stat, errmsg, &
                                k_method=k_method)
    call pushover_scalars(res, stat, scalars)
end subroutine sp_wk_block_pushover

!> The cylinder of a block (half-width b, m; h, m; mass, kg; g, m/s^2; half-length alpha,
!> m) on the same Winkler soil (k, N/m^3; k_method K_*) with the block's rigid p and the
!> same peak imposed moment of the Winkler pushover; slenderness theta_c (rad) when
!> has_theta_c /= 0, else the block's. Returns its r, h (m) and mass (kg).
subroutine sp_wk_equivalent_cylinder(b, h, mass, g, alpha, k, k_method, has_theta_c, theta_c, &
                                     r_c, h_c, mass_c, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_cylinder, only: rocking_body_t, block_props
    use seispulse_winkler, only: winkler_equivalent_cylinder
    implicit none
    !f2py threadsafe
    integer, intent(in) :: k_method, has_theta_c
    real(dp), intent(in) :: b, h, mass, g, alpha, k, theta_c
    real(dp), intent(out) :: r_c, h_c, mass_c
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(rocking_body_t) :: block, cyl
    real(dp), allocatable :: theta_c_opt           ! unallocated: absent (F2008 12.5.2.12)
    errmsg = ''
    r_c = 0.0_dp
    h_c = 0.0_dp
    mass_c = 0.0_dp
    call block_props(b, h, mass, g, block, stat, errmsg)
    if (stat /= SEISPULSE_SUCCESS) return
    if (has_theta_c /= 0) allocate(theta_c_opt, source=theta_c)
    call winkler_equivalent_cylinder(block, alpha, k, cyl, stat, errmsg, theta_c=theta_c_opt, &
                                     k_method=k_method)
    if (stat /= SEISPULSE_SUCCESS) return
    r_c = cyl%r
    h_c = cyl%h
    mass_c = cyl%mass
end subroutine sp_wk_equivalent_cylinder
