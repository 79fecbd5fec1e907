!> Thin f2py layer of seispulse_walls_vy (Veletsos-Younan series) and of the shared wall
!> factors of seispulse_walls_common: plain external subroutines, explicit-shape arrays,
!> stat + errmsg out, no numerics.

!> The first n free-field frequencies (rad/s) of a layer of height H (m), Vs (m/s).
subroutine sp_free_field_frequencies(height, vs, n, omegas, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_walls_common, only: free_field_frequencies
    implicit none
    !f2py threadsafe
    real(dp), intent(in) :: height, vs
    integer, intent(in) :: n
    real(dp), intent(out) :: omegas(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call free_field_frequencies(height, vs, omegas, stat, errmsg)
end subroutine sp_free_field_frequencies

! Hand-written (not in _wrap_loops.txt): puts the element index into the error message.
!> vy_rigid element by element: omega_ratio(i), delta(i), nu(i).
subroutine sp_vy_rigid(n, omega_ratio, delta, nu, tol, q, m, h_ratio, nterms, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_format, only: int_str
    use seispulse_walls_vy, only: vy_rigid
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: n
    real(dp), intent(in) :: omega_ratio(n), delta(n), nu(n), tol
    complex(dp), intent(out) :: q(n), m(n)
    real(dp), intent(out) :: h_ratio(n)
    integer, intent(out) :: nterms(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    integer :: i, k
    errmsg = ''
    stat = SEISPULSE_SUCCESS
    q = (0.0_dp, 0.0_dp)
    m = (0.0_dp, 0.0_dp)
    h_ratio = 0.0_dp
    nterms = 0
    do i = 1, n
        call vy_rigid(omega_ratio(i), delta(i), nu(i), tol, q(i), m(i), h_ratio(i), stat, &
                      errmsg, nterms(i))
        if (stat /= SEISPULSE_SUCCESS) then
            ! "omega_ratio = ..." -> "omega_ratio(i) = ..." for arrays, as the sweep path says
            ! (Python turns it into omega_ratio[i - 1]); tol is one value for all elements
            k = index(errmsg, ' = ')
            if (n > 1 .and. k > 1 .and. errmsg(1:4) /= 'tol ') &
                errmsg = errmsg(1:k - 1)//'('//int_str(i)//')'//errmsg(k:)
            return
        end if
    end do
end subroutine sp_vy_rigid

!> vy_rigid_sweep: many omega_ratios, one delta and nu.
subroutine sp_vy_rigid_sweep(n, omega_ratios, delta, nu, tol, q, m, h_ratio, nterms, stat, &
                             errmsg)
    use seispulse_kinds, only: dp
    use seispulse_walls_vy, only: vy_rigid_sweep
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: n
    real(dp), intent(in) :: omega_ratios(n), delta, nu, tol
    complex(dp), intent(out) :: q(n), m(n)
    real(dp), intent(out) :: h_ratio(n)
    integer, intent(out) :: nterms(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call vy_rigid_sweep(omega_ratios, delta, nu, tol, q, m, h_ratio, stat, errmsg, nterms)
end subroutine sp_vy_rigid_sweep

!> Wall pressure at heights y.
subroutine sp_vy_pressure(omega_ratio, delta, nu, n, y, tol, p, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_walls_vy, only: vy_pressure
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: n
    real(dp), intent(in) :: omega_ratio, delta, nu, y(n), tol
    complex(dp), intent(out) :: p(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call vy_pressure(omega_ratio, delta, nu, y, tol, p, stat, errmsg)
end subroutine sp_vy_pressure

!> Fields at the points (x(i), y(i)).
subroutine sp_vy_fields(omega_ratio, delta, nu, n, x, y, tol, u, v, sigma_x, tau, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_walls_vy, only: vy_fields
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: n
    real(dp), intent(in) :: omega_ratio, delta, nu, x(n), y(n), tol
    complex(dp), intent(out) :: u(n), v(n), sigma_x(n), tau(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call vy_fields(omega_ratio, delta, nu, x, y, tol, u, v, sigma_x, tau, stat, errmsg)
end subroutine sp_vy_fields
