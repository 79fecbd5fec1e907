!> Thin f2py layer: plain external subroutines with explicit-shape arrays, scalar
!> integer/double/fixed-length character arguments only, `stat` + `errmsg` out.
!> No numerics here: each routine translates its arguments and calls the library
!> (style.md section 3: f2py cannot pass derived types, optionals or allocatables).

!> Exponential pulse, dimensionless; beta has length 1 or n.
subroutine sp_exp_pulse(n, tau, nb, beta, full, a, v, d, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_pulses, only: exp_pulse
    implicit none
    integer, intent(in) :: n, nb, full
    real(dp), intent(in) :: tau(n), beta(nb)
    real(dp), intent(out) :: a(n), v(n), d(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call exp_pulse(tau, beta, full /= 0, a, v, d, stat, errmsg)
end subroutine sp_exp_pulse

!> Peak velocity and displacement of the exponential pulse, per beta.
subroutine sp_exp_pulse_peaks(n, beta, full, vg, dg, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_pulses, only: exp_pulse_peaks
    implicit none
    integer, intent(in) :: n, full
    real(dp), intent(in) :: beta(n)
    real(dp), intent(out) :: vg(n), dg(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    integer :: i
    errmsg = ''
    stat = SEISPULSE_SUCCESS
    do i = 1, n
        call exp_pulse_peaks(beta(i), full /= 0, vg(i), dg(i), stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
    end do
end subroutine sp_exp_pulse_peaks

!> Unit-impulse amplitude of the exponential pulse, per beta.
subroutine sp_exp_pulse_impulse_amplitude(n, beta, amp, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_pulses, only: exp_pulse_impulse_amplitude
    implicit none
    integer, intent(in) :: n
    real(dp), intent(in) :: beta(n)
    real(dp), intent(out) :: amp(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    integer :: i
    errmsg = ''
    stat = SEISPULSE_SUCCESS
    do i = 1, n
        call exp_pulse_impulse_amplitude(beta(i), amp(i), stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
    end do
end subroutine sp_exp_pulse_impulse_amplitude

!> Any pulse in SI units; params(np, 9) packed as in pulse_from_params, np = 1 or n.
subroutine sp_pulse_eval(kind, n, t, np, params, a, v, d, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_pulses, only: pulse_t, pulse_eval, pulse_from_params, PULSE_NPARAM
    implicit none
    integer, intent(in) :: kind, n, np
    real(dp), intent(in) :: t(n), params(np, PULSE_NPARAM)
    real(dp), intent(out) :: a(n), v(n), d(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    integer :: i
    errmsg = ''
    if (np == 1) then
        call pulse_eval(pulse_from_params(kind, params(1, :)), t, a, v, d, stat, errmsg)
    else
        stat = SEISPULSE_SUCCESS
        do i = 1, n
            call pulse_eval(pulse_from_params(kind, params(i, :)), t(i:i), a(i:i), v(i:i), &
                            d(i:i), stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
        end do
    end if
end subroutine sp_pulse_eval

!> Pulse kind code from its name.
subroutine sp_pulse_kind(name, kind, stat, errmsg)
    use seispulse_pulses, only: pulse_kind_from_name
    implicit none
    character(len=*), intent(in) :: name
    integer, intent(out) :: kind, stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call pulse_kind_from_name(name, kind, stat, errmsg)
end subroutine sp_pulse_kind
