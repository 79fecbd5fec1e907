!> Thin f2py layer of seispulse_wall_table (the comparison table of one wall): the case
!> arrives as plain scalars, in the order of wall_case_t.

!> The case of the wrappers below, built from plain scalars in one place.
module wrap_wall_case
    use seispulse_kinds, only: dp
    use seispulse_wall_table, only: wall_case_t
    implicit none
    private
    public :: sp_wall_case
contains
    !> Build a wall_case_t from the scalars of the wrappers.
    subroutine sp_wall_case(height, gamma, phi_deg, wall_friction_deg, psi_deg, beta_deg, &
                            gamma_phi, water, gamma_w, gamma_d, kh, kv, alpha_s, nu, delta, &
                            omega_ratio, shape, expo, d_theta, l_over_h, c)
        real(dp), intent(in) :: height, gamma, phi_deg, wall_friction_deg, psi_deg, beta_deg, &
                                gamma_phi, gamma_w, gamma_d, kh, kv, alpha_s, nu, delta, &
                                omega_ratio, expo, d_theta, l_over_h
        integer, intent(in) :: water, shape
        type(wall_case_t), intent(out) :: c
        c = wall_case_t(height=height, gamma=gamma, phi_deg=phi_deg, &
                        wall_friction_deg=wall_friction_deg, psi_deg=psi_deg, beta_deg=beta_deg, &
                        gamma_phi=gamma_phi, water=water, gamma_w=gamma_w, gamma_d=gamma_d, kh=kh, &
                        kv=kv, alpha_s=alpha_s, nu=nu, delta=delta, omega_ratio=omega_ratio, &
                        shape=shape, n=expo, d_theta=d_theta, l_over_h=l_over_h)
    end subroutine sp_wall_case
end module wrap_wall_case

!> The comparison rows (thrust kN/m, z m, moment kNm/m) and the signed kv used.
subroutine sp_wall_comparison(height, gamma, phi_deg, wall_friction_deg, psi_deg, beta_deg, &
                              gamma_phi, water, gamma_w, gamma_d, kh, kv, alpha_s, nu, delta, &
                              omega_ratio, shape, expo, d_theta, l_over_h, thrust, z, moment, &
                              kv_used, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_wall_table, only: wall_case_t, wall_comparison, WALL_ROWS
    use wrap_wall_case, only: sp_wall_case
    implicit none
    !f2py threadsafe
    real(dp), intent(in) :: height, gamma, phi_deg, wall_friction_deg, psi_deg, beta_deg, &
                            gamma_phi, gamma_w, gamma_d, kh, kv, alpha_s, nu, delta, omega_ratio, &
                            expo, d_theta, l_over_h
    integer, intent(in) :: water, shape
    real(dp), intent(out) :: thrust(WALL_ROWS), z(WALL_ROWS), moment(WALL_ROWS), kv_used
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(wall_case_t) :: c
    errmsg = ''
    call sp_wall_case(height, gamma, phi_deg, wall_friction_deg, psi_deg, beta_deg, gamma_phi, &
                      water, gamma_w, gamma_d, kh, kv, alpha_s, nu, delta, omega_ratio, shape, &
                      expo, d_theta, l_over_h, c)
    call wall_comparison(c, thrust, z, moment, kv_used, stat, errmsg)
end subroutine sp_wall_comparison

!> Pressures against depth (kPa), columns as in wall_pressure_profile.
subroutine sp_wall_pressure(height, gamma, phi_deg, wall_friction_deg, psi_deg, beta_deg, &
                            gamma_phi, water, gamma_w, gamma_d, kh, kv, alpha_s, nu, delta, &
                            omega_ratio, shape, expo, d_theta, l_over_h, nd, depth, p, stat, &
                            errmsg)
    use seispulse_kinds, only: dp
    use seispulse_wall_table, only: wall_case_t, wall_pressure_profile, WALL_PROFILE_COLUMNS
    use wrap_wall_case, only: sp_wall_case
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: nd
    real(dp), intent(in) :: height, gamma, phi_deg, wall_friction_deg, psi_deg, beta_deg, &
                            gamma_phi, gamma_w, gamma_d, kh, kv, alpha_s, nu, delta, omega_ratio, &
                            expo, d_theta, l_over_h
    integer, intent(in) :: water, shape, nd
    real(dp), intent(in) :: depth(nd)
    real(dp), intent(out) :: p(nd, WALL_PROFILE_COLUMNS)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(wall_case_t) :: c
    errmsg = ''
    call sp_wall_case(height, gamma, phi_deg, wall_friction_deg, psi_deg, beta_deg, gamma_phi, &
                      water, gamma_w, gamma_d, kh, kv, alpha_s, nu, delta, omega_ratio, shape, &
                      expo, d_theta, l_over_h, c)
    call wall_pressure_profile(c, depth, p, stat, errmsg)
end subroutine sp_wall_pressure
