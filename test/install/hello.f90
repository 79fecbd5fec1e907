!> Install check: a design code outside the source tree that does `use seispulse` and
!> links against the installed library (pkg-config). Prints `ok` on success, otherwise
!> one line per failed check and `error stop 1`.
program hello
    use seispulse, only: dp, SEISPULSE_SUCCESS, exp_pulse_peaks, half_sine_pulse, pulse_t, &
                         pulse_eval, solve_linear, half_cycle, half_cycle_t
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_negative_inf
    implicit none

    real(dp), parameter :: pi = 3.14159265358979323846264338327950288_dp
    type(pulse_t) :: p
    type(half_cycle_t) :: h
    real(dp) :: vg, dg, t(1), a(1), v(1), d(1), m(2, 2), b(2), x(2)
    integer :: stat, nfail
    character(len=200) :: msg

    nfail = 0
    msg = ''

    ! exponential pulse, beta = 0 (exactly the triangle): vg = 1/2, dg = vg/2
    call exp_pulse_peaks(0.0_dp, .false., vg, dg, stat, msg)
    call expect(stat == SEISPULSE_SUCCESS, 'exp_pulse_peaks: stat /= 0: '//trim(msg))
    call expect(vg == 0.5_dp, 'exp_pulse_peaks: vg /= 0.5')
    call expect(abs(dg - 0.25_dp) <= 1.0e-15_dp, 'exp_pulse_peaks: dg /= 0.25')

    ! sliding block under the rectangular half cycle: u_m = (1 - eta)/(2 eta) (Newmark)
    call half_cycle(0.25_dp, ieee_value(1.0_dp, ieee_negative_inf), 1.0_dp, h, stat, msg)
    call expect(stat == SEISPULSE_SUCCESS, 'half_cycle: stat /= 0: '//trim(msg))
    call expect(abs(h%um - 1.5_dp) <= 1.0e-15_dp, 'half_cycle: um /= 1.5')

    ! half-sine pulse, amplitude 1, duration 1: v(1) = 2/pi
    p = half_sine_pulse(1.0_dp, 1.0_dp)
    t = 1.0_dp
    call pulse_eval(p, t, a, v, d, stat, msg)
    call expect(stat == SEISPULSE_SUCCESS, 'pulse_eval: stat /= 0: '//trim(msg))
    call expect(abs(v(1) - 2.0_dp / pi) <= 4.0e-16_dp, 'pulse_eval: v(1) /= 2/pi')

    ! a LAPACK call through the library (checks that the link pulls LAPACK in)
    m = reshape([2.0_dp, 1.0_dp, 1.0_dp, 3.0_dp], [2, 2])
    b = [3.0_dp, 4.0_dp]
    call solve_linear(m, b, x, stat, msg)
    call expect(stat == SEISPULSE_SUCCESS, 'solve_linear: stat /= 0: '//trim(msg))
    call expect(all(abs(x - 1.0_dp) <= 1.0e-14_dp), 'solve_linear: x /= [1, 1]')

    if (nfail > 0) error stop 1
    print '(a)', 'ok'

contains

    subroutine expect(condition, what)
        logical, intent(in) :: condition
        character(len=*), intent(in) :: what
        if (.not. condition) then
            nfail = nfail + 1
            print '(a)', 'FAIL '//what
        end if
    end subroutine expect

end program hello
