!> Shared pieces of the elastodynamic retaining-wall solutions (doc/walls.md):
!> the compressibility factors psi(nu), the free-field frequencies of the layer, the
!> argument checks every wall routine makes, and the square root on the branch the
!> physics wants.
!>
!> Model (doc/walls.md section 1): a viscoelastic layer of height H on rigid rock, shear modulus
!> G* = G(1 + i delta) with delta the loss factor (about twice the hysteretic damping
!> ratio), Poisson's ratio nu, harmonic rock acceleration Xg exp(i omega t). The wall
!> solutions give the dynamic increment only, never the geostatic thrust.
module seispulse_walls_common
    use seispulse_kinds, only: dp
    use seispulse_special, only: pi
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, SEISPULSE_SINGULAR, &
                                set_error
    use seispulse_checks, only: outside
    use seispulse_format, only: real_str, int_str
    implicit none
    private

    public :: wall_psi_t, wall_psi, free_field_frequencies, check_nu, check_delta, &
              check_omega_ratio, sqrt_branch, resonance_error, inv_one_plus_i

    !> Compressibility factors of doc/walls.md section 1 (dimensionless).
    type :: wall_psi_t
        real(dp) :: e = 0.0_dp      !! psi_e = sqrt((2 - nu)/(1 - nu)): decay along x (2.10)
        real(dp) :: o = 0.0_dp      !! psi_o = sqrt(2/(1 - nu)): sigma_x = psi_o^2 G* du/dx
        !> psi_sigma = psi_o^2/psi_e = 2/sqrt((1 - nu)(2 - nu)): wall stresses, thrust, moment
        real(dp) :: sigma = 0.0_dp
        real(dp) :: v = 0.0_dp      !! psi_v = nu/sqrt((1 - nu)(2 - nu)): v (2.31)
        real(dp) :: t = 0.0_dp      !! psi_t = sqrt(2(1 - nu)/(1 - 2 nu)): Matsuo-Ohara (v = 0)
    end type wall_psi_t

contains

    !> nu must lie in [0, 0.5): the message names `nu` and the range.
    pure subroutine check_nu(nu, stat, errmsg)
        real(dp), intent(in) :: nu                         !! Poisson's ratio of the soil
        integer, intent(out) :: stat !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg !! "nu: ..." on error
        stat = SEISPULSE_SUCCESS
        if (outside(nu, 0.0_dp, 0.5_dp, .false., .true.)) &
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'nu = '//real_str(nu)// &
                           ': Poisson''s ratio must lie in [0, 0.5)')
    end subroutine check_nu

    !> delta must be finite and >= 0 (a loss factor; G* = G(1 + i delta)).
    pure subroutine check_delta(delta, stat, errmsg)
        real(dp), intent(in) :: delta                      !! soil loss factor
        integer, intent(out) :: stat !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg !! "delta: ..." on error
        stat = SEISPULSE_SUCCESS
        if (outside(delta, 0.0_dp, huge(1.0_dp), .false., .false.)) &
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'delta = '//real_str(delta)// &
                           ': the loss factor must be finite and >= 0')
    end subroutine check_delta

    !> omega_ratio (omega/omega_1, or omega over the reference frequency of the routine)
    !> must be finite and >= 0.
    pure subroutine check_omega_ratio(omega_ratio, stat, errmsg)
        real(dp), intent(in) :: omega_ratio                !! excitation over reference frequency
        integer, intent(out) :: stat !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg !! "omega_ratio: ..." on error
        stat = SEISPULSE_SUCCESS
        if (outside(omega_ratio, 0.0_dp, huge(1.0_dp), .false., .false.)) &
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'omega_ratio = '// &
                           real_str(omega_ratio)//': must be finite and >= 0')
    end subroutine check_omega_ratio

    !> The resonance refusal shared by the wall solutions: zero damping exactly at a
    !> natural (or cut-off) frequency gives an unbounded response.
    pure subroutine resonance_error(omega_ratio, where, stat, errmsg)
        real(dp), intent(in) :: omega_ratio                !! the offending frequency ratio
        character(len=*), intent(in) :: where              !! which frequency, e.g. "omega_1 x 3"
        integer, intent(out) :: stat                       !! SEISPULSE_SINGULAR
        character(len=*), intent(inout), optional :: errmsg !! message naming omega_ratio and delta
        call set_error(stat, errmsg, SEISPULSE_SINGULAR, 'omega_ratio = '//real_str(omega_ratio)// &
                       ': resonance at '//where//' with delta = 0; the undamped response is '// &
                       'unbounded (give delta > 0 or move off the resonance)')
    end subroutine resonance_error

    !> Compressibility factors for Poisson's ratio nu in [0, 0.5).
    pure subroutine wall_psi(nu, psi, stat, errmsg)
        real(dp), intent(in) :: nu                         !! Poisson's ratio, 0 <= nu < 0.5
        type(wall_psi_t), intent(out) :: psi               !! the five factors
        integer, intent(out) :: stat !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg !! message on error
        call check_nu(nu, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        psi%e = sqrt((2.0_dp - nu)/(1.0_dp - nu))
        psi%o = sqrt(2.0_dp/(1.0_dp - nu))
        psi%sigma = 2.0_dp/sqrt((1.0_dp - nu)*(2.0_dp - nu))
        psi%v = nu/sqrt((1.0_dp - nu)*(2.0_dp - nu))
        psi%t = sqrt(2.0_dp*(1.0_dp - nu)/(1.0_dp - 2.0_dp*nu))
    end subroutine wall_psi

    !> Natural frequencies of the free-field layer (2.22): omega_k = (2k - 1) pi Vs/(2H),
    !> k = 1..size(omegas), in rad/s.
    pure subroutine free_field_frequencies(height, vs, omegas, stat, errmsg)
        real(dp), intent(in) :: height                     !! layer (wall) height H, m, > 0
        real(dp), intent(in) :: vs                         !! shear-wave velocity Vs, m/s, > 0
        real(dp), intent(out) :: omegas(:) !! omega_1, omega_3/3 ... : (2k - 1) pi Vs/(2H), rad/s
        integer, intent(out) :: stat !! SEISPULSE_SUCCESS or SEISPULSE_INVALID_INPUT
        character(len=*), intent(inout), optional :: errmsg !! message on error
        integer :: k
        omegas = 0.0_dp
        stat = SEISPULSE_SUCCESS
        if (outside(height, 0.0_dp, huge(1.0_dp), .true., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'height = '//real_str(height)// &
                           ': the wall height H (m) must be finite and > 0')
            return
        end if
        if (outside(vs, 0.0_dp, huge(1.0_dp), .true., .false.)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'vs = '//real_str(vs)// &
                           ': the shear-wave velocity (m/s) must be finite and > 0')
            return
        end if
        do k = 1, size(omegas)
            omegas(k) = real(2*k - 1, dp)*(pi*vs/(2.0_dp*height))
        end do
        if (size(omegas) > 0) then
            if (.not. (omegas(size(omegas)) <= huge(1.0_dp))) &
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'vs/height: the '// &
                               int_str(size(omegas))//' frequencies overflow')
        end if
    end subroutine free_field_frequencies

    !> sqrt(z) on the branch of the delta -> 0+ limit: Re >= 0, and for a negative real
    !> z (delta = 0 above a resonance) +i sqrt(-z), whatever the sign of a zero imaginary
    !> part (doc/walls.md section 2: sqrt(-x - 0i) = -i sqrt(x) would flip the radiation sign).
    elemental function sqrt_branch(z) result(w)
        complex(dp), intent(in) :: z  !! argument whose imaginary part is mathematically >= 0
        complex(dp) :: w
        if (aimag(z) > 0.0_dp) then
            w = sqrt(z)
        else
            w = sqrt(cmplx(real(z, dp), 0.0_dp, dp))
        end if
    end function sqrt_branch

    !> 1/(1 + i delta), the damping factor of G* = G(1 + i delta), without overflow of
    !> delta^2 for large delta.
    elemental function inv_one_plus_i(delta) result(w)
        real(dp), intent(in) :: delta  !! hysteretic damping factor delta (dimensionless)
        complex(dp) :: w
        real(dp) :: r, d
        if (delta <= 1.0_dp) then
            d = 1.0_dp + delta*delta
            w = cmplx(1.0_dp/d, -delta/d, dp)
        else
            r = 1.0_dp/delta
            d = 1.0_dp + r*r
            w = cmplx(r*r/d, -r/d, dp)
        end if
    end function inv_one_plus_i

end module seispulse_walls_common
