!> Thin f2py layer of seispulse_codes (EN 1998 earth-pressure checks and spectra): plain
!> external subroutines, explicit-shape arrays, int flags, `stat` + `errmsg` out, no
!> numerics.

!> EN 1998-5 (7.1)-(7.3): kh, kv (magnitude) from alpha, S, r and avg/ag.
subroutine sp_ec8_seismic_coefficients(alpha, s, r, vertical_ratio, kh, kv, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_codes, only: ec8_seismic_coefficients
    implicit none
    !f2py threadsafe
    real(dp), intent(in) :: alpha, s, r, vertical_ratio
    real(dp), intent(out) :: kh, kv
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call ec8_seismic_coefficients(alpha, s, r, vertical_ratio, kh, kv, stat, errmsg)
end subroutine sp_ec8_seismic_coefficients

!> avg/ag of EN 1998-1 Table 3.4 (NaN for an unknown type).
subroutine sp_ec8_vertical_ratio(spectrum_type, ratio)
    use seispulse_kinds, only: dp
    use seispulse_codes, only: ec8_vertical_ratio
    implicit none
    !f2py threadsafe
    integer, intent(in) :: spectrum_type
    real(dp), intent(out) :: ratio
    ratio = ec8_vertical_ratio(spectrum_type)
end subroutine sp_ec8_vertical_ratio

!> r of EN 1998-5 Table 7.1; wall_type 1, 2, 3 as EC8_WALL_*.
subroutine sp_ec8_r_factor(wall_type, r, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_codes, only: ec8_r_factor
    implicit none
    !f2py threadsafe
    integer, intent(in) :: wall_type
    real(dp), intent(out) :: r
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call ec8_r_factor(wall_type, r, stat, errmsg)
end subroutine sp_ec8_r_factor

!> Mononobe-Okabe K and theta; passive 0/1; k_e3 = EN E.3 beyond the active limit.
subroutine sp_mononobe_okabe(phi_deg, kh, kv, delta_deg, psi_deg, beta_deg, passive, gamma_phi, &
                             k, theta, k_e3, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_codes, only: mononobe_okabe
    implicit none
    !f2py threadsafe
    real(dp), intent(in) :: phi_deg, kh, kv, delta_deg, psi_deg, beta_deg, gamma_phi
    integer, intent(in) :: passive
    real(dp), intent(out) :: k, theta, k_e3
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call mononobe_okabe(phi_deg, kh, kv, delta_deg, psi_deg, beta_deg, passive /= 0, gamma_phi, &
                        k, theta, stat, errmsg, k_e3)
end subroutine sp_mononobe_okabe

!> EN 1998-5 Annex E thrust; out = [k, theta, e_soil, e_static, e_dynamic, e_ws, e_wd,
!> total, z_static, z_dynamic, z_ws, z_wd, z_total, m_base, k_static].
subroutine sp_ec8_thrust(height, gamma, phi_deg, delta_deg, psi_deg, beta_deg, kh, kv, &
                         water_case, gamma_w, gamma_d, gamma_phi, out, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_codes, only: ec8_thrust, ec8_thrust_t
    implicit none
    !f2py threadsafe
    real(dp), intent(in) :: height, gamma, phi_deg, delta_deg, psi_deg, beta_deg, kh, kv, &
                            gamma_w, gamma_d, gamma_phi
    integer, intent(in) :: water_case
    real(dp), intent(out) :: out(15)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(ec8_thrust_t) :: res
    errmsg = ''
    call ec8_thrust(height, gamma, phi_deg, delta_deg, psi_deg, beta_deg, kh, kv, water_case, &
                    gamma_w, gamma_d, gamma_phi, res, stat, errmsg)
    out = [res%k, res%theta, res%e_soil, res%e_static, res%e_dynamic, res%e_ws, res%e_wd, &
           res%total, res%z_static, res%z_dynamic, res%z_ws, res%z_wd, res%z_total, res%m_base, &
           res%k_static]
end subroutine sp_ec8_thrust

!> Westergaard pressure at depths z below the free water surface.
subroutine sp_westergaard_pressure(n, kh, gamma_w, h_water, z, q, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_codes, only: westergaard_pressure
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: n
    real(dp), intent(in) :: kh, gamma_w, h_water, z(n)
    real(dp), intent(out) :: q(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call westergaard_pressure(kh, gamma_w, h_water, z, q, stat, errmsg)
end subroutine sp_westergaard_pressure

!> EN 1998-5 rigid wall: alpha S gamma H^2 at H/2.
subroutine sp_ec8_rigid_thrust(alpha_s, gamma, height, thrust, z, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_codes, only: ec8_rigid_thrust
    implicit none
    !f2py threadsafe
    real(dp), intent(in) :: alpha_s, gamma, height
    real(dp), intent(out) :: thrust, z
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call ec8_rigid_thrust(alpha_s, gamma, height, thrust, z, stat, errmsg)
end subroutine sp_ec8_rigid_thrust

!> Seed & Whitman: 3/8 kh gamma H^2 at 0.6 H.
subroutine sp_seed_whitman_increment(kh, gamma, height, thrust, z, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_codes, only: seed_whitman_increment
    implicit none
    !f2py threadsafe
    real(dp), intent(in) :: kh, gamma, height
    real(dp), intent(out) :: thrust, z
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call seed_whitman_increment(kh, gamma, height, thrust, z, stat, errmsg)
end subroutine sp_seed_whitman_increment

!> Wood (as quoted): kh gamma H^2 at 0.6 H.
subroutine sp_wood_thrust(alpha_s, gamma, height, thrust, z, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_codes, only: wood_thrust
    implicit none
    !f2py threadsafe
    real(dp), intent(in) :: alpha_s, gamma, height
    real(dp), intent(out) :: thrust, z
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call wood_thrust(alpha_s, gamma, height, thrust, z, stat, errmsg)
end subroutine sp_wood_thrust

!> S, TB, TC, TD of EN 1998-1 Tables 3.2/3.3; ground 1..5 = A..E.
subroutine sp_ec8_ground_parameters(spectrum_type, ground, s, tb, tc, td, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_codes, only: ec8_ground_parameters
    implicit none
    !f2py threadsafe
    integer, intent(in) :: spectrum_type, ground
    real(dp), intent(out) :: s, tb, tc, td
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call ec8_ground_parameters(spectrum_type, ground, s, tb, tc, td, stat, errmsg)
end subroutine sp_ec8_ground_parameters

! Hand-written (not in _wrap_loops.txt): checks all xi, then one elemental call; index in errmsg.
!> eta(xi) per element; stops at the first bad xi (xi_percent(i) in the message).
subroutine sp_ec8_damping_correction(n, xi_percent, eta, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_format, only: int_str
    use seispulse_codes, only: ec8_damping_correction, ec8_check_damping
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: n
    real(dp), intent(in) :: xi_percent(n)
    real(dp), intent(out) :: eta(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    integer :: i
    errmsg = ''
    eta = 0.0_dp
    do i = 1, n
        call ec8_check_damping(xi_percent(i), stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) then
            if (n > 1) errmsg = 'xi_percent('//int_str(i)//')'//errmsg(len('xi_percent') + 1:)
            return
        end if
    end do
    eta = ec8_damping_correction(xi_percent)
end subroutine sp_ec8_damping_correction

!> Elastic spectrum EN 1998-1 (3.2)-(3.5).
subroutine sp_ec8_elastic_spectrum(n, periods, ag, spectrum_type, ground, xi_percent, se, stat, &
                                   errmsg)
    use seispulse_kinds, only: dp
    use seispulse_codes, only: ec8_elastic_spectrum
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: n, spectrum_type, ground
    real(dp), intent(in) :: periods(n), ag, xi_percent
    real(dp), intent(out) :: se(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call ec8_elastic_spectrum(periods, ag, spectrum_type, ground, xi_percent, se, stat, errmsg)
end subroutine sp_ec8_elastic_spectrum

!> Design spectrum EN 1998-1 (3.13)-(3.16).
subroutine sp_ec8_design_spectrum(n, periods, ag, spectrum_type, ground, q, beta, sd, stat, &
                                  errmsg)
    use seispulse_kinds, only: dp
    use seispulse_codes, only: ec8_design_spectrum
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: n, spectrum_type, ground
    real(dp), intent(in) :: periods(n), ag, q, beta
    real(dp), intent(out) :: sd(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call ec8_design_spectrum(periods, ag, spectrum_type, ground, q, beta, sd, stat, errmsg)
end subroutine sp_ec8_design_spectrum

!> a_gR (g) of a seismic zone of a National Annex; annex as EC8_ANNEX_*.
subroutine sp_ec8_reference_pga(annex, zone, agr, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_codes, only: ec8_reference_pga
    implicit none
    !f2py threadsafe
    integer, intent(in) :: annex, zone
    real(dp), intent(out) :: agr
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call ec8_reference_pga(annex, zone, agr, stat, errmsg)
end subroutine sp_ec8_reference_pga

!> ag = gamma_I a_gR (g) of a spectrum: ag given (NaN: not) or a zone (0: not) of annex.
subroutine sp_ec8_design_ag(ag, annex, zone, importance, ag_out, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_codes, only: ec8_design_ag
    implicit none
    !f2py threadsafe
    real(dp), intent(in) :: ag, importance
    integer, intent(in) :: annex, zone
    real(dp), intent(out) :: ag_out
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call ec8_design_ag(ag, annex, zone, importance, ag_out, stat, errmsg)
end subroutine sp_ec8_design_ag
