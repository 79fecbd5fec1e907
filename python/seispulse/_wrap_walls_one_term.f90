!> Thin f2py layer of seispulse_walls_one_term (one-term wall solution): plain external
!> subroutines, explicit-shape arrays, `stat` + `errmsg` out, no numerics. The stiffness
!> exponent is `expo` here (n is an array size in f2py signatures).

!> Shape constants (one_term_shape).
subroutine sp_ot_shape(shape, expo, a_oc, l_factor, mass_factor, s0, s1, h_ratio, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_walls_one_term, only: one_term_shape_t, one_term_shape
    implicit none
    !f2py threadsafe
    integer, intent(in) :: shape
    real(dp), intent(in) :: expo
    real(dp), intent(out) :: a_oc, l_factor, mass_factor, s0, s1, h_ratio
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(one_term_shape_t) :: c
    errmsg = ''
    call one_term_shape(shape, expo, c, stat, errmsg)
    a_oc = c%a_oc
    l_factor = c%l_factor
    mass_factor = c%mass_factor
    s0 = c%s0
    s1 = c%s1
    h_ratio = c%h_ratio
end subroutine sp_ot_shape

!> one_term_pressure at heights y.
subroutine sp_ot_pressure(omega_ratio, delta, nu, shape, expo, d_theta, l_over_h, ny, y, p, &
                          stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_walls_one_term, only: one_term_pressure
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: ny
    integer, intent(in) :: ny, shape
    real(dp), intent(in) :: omega_ratio, delta, nu, expo, d_theta, l_over_h, y(ny)
    complex(dp), intent(out) :: p(ny)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call one_term_pressure(omega_ratio, delta, nu, shape, expo, d_theta, l_over_h, y, p, stat, &
                           errmsg)
end subroutine sp_ot_pressure

!> one_term_displacement at the points (x(i), y(i)).
subroutine sp_ot_displacement(omega_ratio, delta, nu, shape, expo, d_theta, l_over_h, np, x, y, &
                              u, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_walls_one_term, only: one_term_displacement
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: np
    integer, intent(in) :: np, shape
    real(dp), intent(in) :: omega_ratio, delta, nu, expo, d_theta, l_over_h, x(np), y(np)
    complex(dp), intent(out) :: u(np)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call one_term_displacement(omega_ratio, delta, nu, shape, expo, d_theta, l_over_h, x, y, u, &
                               stat, errmsg)
end subroutine sp_ot_displacement
