! Thin layer of seispulse_clay_footing (doc/winkler.md "Inelastic soil": a circular footing
! on undrained clay, [AD11] chapter 3) for seispulse.winkler: plain subroutines,
! explicit-shape arrays, inline !f2py lines (gen_binding.py reads them). No numerics here.
! The degradation coefficients cross the layer one by one (k_el, kr_c1, kr_c2, a_poly(0:4)
! as a_poly(5), b1, b2, c1, c2, log_base; NaN: not given) and nc (the bearing factor) only
! when has_nc /= 0.

!> Vertical capacity N_ult (N), factor of safety SF and chi = 1/SF per (su Pa, r m,
!> weight N); nc when has_nc /= 0 (default pi + 3).
subroutine sp_clay_bearing(n, su, r, weight, has_nc, nc, n_ult, sf, chi, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_clay_footing, only: clay_bearing
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: n, has_nc
    real(dp), intent(in) :: su(n), r(n), weight(n), nc
    real(dp), intent(out) :: n_ult(n), sf(n), chi(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    integer :: i
    errmsg = ''
    stat = SEISPULSE_SUCCESS
    n_ult = 0.0_dp
    sf = 0.0_dp
    chi = 0.0_dp
    do i = 1, n
        if (has_nc /= 0) then
            call clay_bearing(su(i), r(i), weight(i), n_ult(i), sf(i), chi(i), stat, errmsg, nc)
        else
            call clay_bearing(su(i), r(i), weight(i), n_ult(i), sf(i), chi(i), stat, errmsg)
        end if
        if (stat /= SEISPULSE_SUCCESS) return
    end do
end subroutine sp_clay_bearing

!> Moment capacity (N m) of a circular footing per (su Pa, r m, chi); model CAPACITY_*;
!> nc when has_nc /= 0.
subroutine sp_clay_moment_capacity(n, su, r, chi, model, has_nc, nc, m_ult, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_clay_footing, only: moment_capacity_circle
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: n, model, has_nc
    real(dp), intent(in) :: su(n), r(n), chi(n), nc
    real(dp), intent(out) :: m_ult(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    integer :: i
    errmsg = ''
    stat = SEISPULSE_SUCCESS
    m_ult = 0.0_dp
    do i = 1, n
        if (has_nc /= 0) then
            call moment_capacity_circle(su(i), r(i), chi(i), model, m_ult(i), stat, errmsg, nc)
        else
            call moment_capacity_circle(su(i), r(i), chi(i), model, m_ult(i), stat, errmsg)
        end if
        if (stat /= SEISPULSE_SUCCESS) return
    end do
end subroutine sp_clay_moment_capacity

!> Inelastic rotational pushover of a cylinder (r, h m; weight N) on clay (g_mod Pa, nu,
!> su Pa) with the user's degradation coefficients, on the rotations theta (rad):
!> curve(n, IP_NCOL) in the columns IP_*; scalars(16) = n_ult (N), sf, chi, hk_r (N m/rad),
!> k_ratio, kappa, k_r0 (N m/rad), theta_up (rad), a, b, c (-), max_moment (N m),
!> theta_at_max_moment (rad), max_force_over_weight (-), theta_at_max, theta_overturn (rad);
!> flags(3) = no_uplift, weak_zone, kr_discontinuous (1/0); kr_jump (-).
subroutine sp_clay_inelastic_pushover(r, h, weight, g_mod, nu, su, k_el, kr_c1, kr_c2, a_poly, &
                                      b1, b2, c1, c2, log_base, has_nc, nc, n, theta, curve, &
                                      scalars, flags, kr_jump, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_clay_footing, only: degradation_coeffs_t, inelastic_pushover_t, &
                                      inelastic_pushover, IP_NCOL
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: has_nc, n
    real(dp), intent(in) :: r, h, weight, g_mod, nu, su, k_el, kr_c1, kr_c2, a_poly(5), b1, b2
    real(dp), intent(in) :: c1, c2, log_base, nc, theta(n)
    real(dp), intent(out) :: curve(n, IP_NCOL), scalars(16), kr_jump
    integer, intent(out) :: flags(3)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(degradation_coeffs_t) :: coeffs
    type(inelastic_pushover_t) :: res
    errmsg = ''
    curve = 0.0_dp
    coeffs = degradation_coeffs_t(k_el=k_el, kr_c1=kr_c1, kr_c2=kr_c2, a_poly=a_poly, b1=b1, &
                                  b2=b2, c1=c1, c2=c2, log_base=log_base)
    if (has_nc /= 0) then
        call inelastic_pushover(r, h, weight, g_mod, nu, su, coeffs, theta, curve, res, stat, &
                                errmsg, nc)
    else
        call inelastic_pushover(r, h, weight, g_mod, nu, su, coeffs, theta, curve, res, stat, &
                                errmsg)
    end if
    ! the scalars are returned with a failed status too (no_uplift names its cause)
    scalars = [res%n_ult, res%sf, res%chi, res%hk_r, res%k_ratio, res%kappa, res%k_r0, &
               res%theta_up, res%a, res%b, res%c, res%max_moment, res%theta_at_max_moment, &
               res%max_force_over_weight, res%theta_at_max, res%theta_overturn]
    flags = [merge(1, 0, res%no_uplift), merge(1, 0, res%weak_zone), &
             merge(1, 0, res%kr_discontinuous)]
    kr_jump = res%kr_jump
end subroutine sp_clay_inelastic_pushover

!> Initial-stiffness ratio k/k_el (-) and kappa = k_el k/k_el (-) per chi = 1/SF, with the
!> user's k_el, kr_c1, kr_c2 (NaN: not given).
subroutine sp_clay_stiffness_ratio(n, chi, k_el, kr_c1, kr_c2, k_ratio, kappa, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_clay_footing, only: degradation_coeffs_t, initial_stiffness_ratio
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: n
    real(dp), intent(in) :: chi(n), k_el, kr_c1, kr_c2
    real(dp), intent(out) :: k_ratio(n), kappa(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(degradation_coeffs_t) :: coeffs
    integer :: i
    errmsg = ''
    stat = SEISPULSE_SUCCESS
    k_ratio = 0.0_dp
    kappa = 0.0_dp
    coeffs = degradation_coeffs_t(k_el=k_el, kr_c1=kr_c1, kr_c2=kr_c2)
    do i = 1, n
        call initial_stiffness_ratio(chi(i), coeffs, k_ratio(i), stat, errmsg, kappa=kappa(i))
        if (stat /= SEISPULSE_SUCCESS) return
    end do
end subroutine sp_clay_stiffness_ratio

!> Gaussian correction G(chi; x) (-) per (chi, x = theta/theta_up), with the user's
!> a_poly(0:4) (as a_poly(5)), b1, b2, c1, c2 and log_base (NaN: not given).
subroutine sp_clay_gaussian(n, chi, x, a_poly, b1, b2, c1, c2, log_base, g_corr, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_clay_footing, only: degradation_coeffs_t, gaussian_correction
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: n
    real(dp), intent(in) :: chi(n), x(n), a_poly(5), b1, b2, c1, c2, log_base
    real(dp), intent(out) :: g_corr(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(degradation_coeffs_t) :: coeffs
    integer :: i
    errmsg = ''
    stat = SEISPULSE_SUCCESS
    g_corr = 0.0_dp
    coeffs = degradation_coeffs_t(a_poly=a_poly, b1=b1, b2=b2, c1=c1, c2=c2, log_base=log_base)
    do i = 1, n
        call gaussian_correction(chi(i), x(i), coeffs, g_corr(i), stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
    end do
end subroutine sp_clay_gaussian
