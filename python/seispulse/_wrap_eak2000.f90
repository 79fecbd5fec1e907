!> Thin f2py layer of seispulse_eak2000 (EAK 2000 spectra): plain external subroutines,
!> explicit-shape arrays, int flags, `stat` + `errmsg` out, no numerics.

!> T1, T2 (s) of soil category 1..4 = A..D (5 = X is refused).
subroutine sp_eak2000_ground_parameters(ground, t1, t2, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_eak2000, only: eak2000_ground_parameters
    implicit none
    !f2py threadsafe
    integer, intent(in) :: ground
    real(dp), intent(out) :: t1, t2
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call eak2000_ground_parameters(ground, t1, t2, stat, errmsg)
end subroutine sp_eak2000_ground_parameters

!> alpha = A/g of zone `zone` of map `zone_map` (1 = 2003, 2 = 2000).
subroutine sp_eak2000_zone_acceleration(zone, zone_map, alpha, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_eak2000, only: eak2000_zone_acceleration
    implicit none
    !f2py threadsafe
    integer, intent(in) :: zone, zone_map
    real(dp), intent(out) :: alpha
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call eak2000_zone_acceleration(zone, zone_map, alpha, stat, errmsg)
end subroutine sp_eak2000_zone_acceleration

!> gamma_I of importance category 1..4.
subroutine sp_eak2000_importance_factor(category, gamma_i, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_eak2000, only: eak2000_importance_factor
    implicit none
    !f2py threadsafe
    integer, intent(in) :: category
    real(dp), intent(out) :: gamma_i
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call eak2000_importance_factor(category, gamma_i, stat, errmsg)
end subroutine sp_eak2000_importance_factor

!> The spectral amplification beta0 of EAK 2000 (EAK_BETA0).
subroutine sp_eak2000_beta0(beta0)
    use seispulse_kinds, only: dp
    use seispulse_eak2000, only: EAK_BETA0
    implicit none
    !f2py threadsafe
    real(dp), intent(out) :: beta0
    beta0 = EAK_BETA0
end subroutine sp_eak2000_beta0

! Hand-written (not in _wrap_loops.txt): checks all xi, then one elemental call; index in errmsg.
!> eta(xi) with the lower limit eta_min per element; stops at the first bad xi.
subroutine sp_eak2000_damping_correction(n, xi_percent, eta_min, eta, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_format, only: int_str
    use seispulse_eak2000, only: eak2000_damping_correction, eak2000_check_damping
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: n
    real(dp), intent(in) :: xi_percent(n), eta_min
    real(dp), intent(out) :: eta(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    integer :: i
    errmsg = ''
    eta = 0.0_dp
    do i = 1, n
        call eak2000_check_damping(xi_percent(i), eta_min, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) then
            if (n > 1 .and. errmsg(1:len('xi_percent ')) == 'xi_percent ') &
                errmsg = 'xi_percent('//int_str(i)//')'//errmsg(len('xi_percent') + 1:)
            return
        end if
    end do
    eta = eak2000_damping_correction(xi_percent, eta_min)
end subroutine sp_eak2000_damping_correction

!> Design spectrum Phi_d of EAK 2000 (K.1)-(K.3), (K.5); phi_d in g.
subroutine sp_eak2000_design_spectrum(n, periods, alpha, ground, importance, q, theta, &
                                      xi_percent, eta_min, lower_bound, phi_d, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_eak2000, only: eak2000_design_spectrum
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: n, ground
    real(dp), intent(in) :: periods(n), alpha, importance, q, theta, xi_percent, eta_min, &
                            lower_bound
    real(dp), intent(out) :: phi_d(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call eak2000_design_spectrum(periods, alpha, ground, importance, q, theta, xi_percent, &
                                 eta_min, lower_bound, phi_d, stat, errmsg)
end subroutine sp_eak2000_design_spectrum

!> Elastic spectrum Phi_e of EAK 2000 (K.1)-(K.3) with q = theta = 1, (K.6); phi_e in g.
subroutine sp_eak2000_elastic_spectrum(n, periods, alpha, ground, importance, xi_percent, &
                                       eta_min, exponent, phi_e, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_eak2000, only: eak2000_elastic_spectrum
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: n, ground
    real(dp), intent(in) :: periods(n), alpha, importance, xi_percent, eta_min, exponent
    real(dp), intent(out) :: phi_e(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call eak2000_elastic_spectrum(periods, alpha, ground, importance, xi_percent, eta_min, &
                                  exponent, phi_e, stat, errmsg)
end subroutine sp_eak2000_elastic_spectrum
