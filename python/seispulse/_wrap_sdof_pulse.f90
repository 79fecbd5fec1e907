!> Thin f2py layer of seispulse_sdof_closed (linear oscillator closed forms): plain external
!> subroutines, explicit-shape arrays, int flags, `stat` + `errmsg` out, no numerics.
!> Pulses arrive as (kind, params(PULSE_NPARAM)) packed as in pulse_from_params.

!> Harmonic base motion; law 1 sine, 2 cosine; transient 0/1.
subroutine sp_harmonic_response(n, t, w0, period, ratio, damping, law, transient, z, v, a, &
                                stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_sdof_closed, only: harmonic_response
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: n, law, transient
    real(dp), intent(in) :: t(n), w0, period, ratio, damping
    real(dp), intent(out) :: z(n), v(n), a(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call harmonic_response(t, w0, period, ratio, damping, law, transient /= 0, z, v, a, stat, &
                           errmsg)
end subroutine sp_harmonic_response

!> Undamped rectangular pulse, book forms.
subroutine sp_rect_pulse_response(n, t, w0, t1, period, z, v, a, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_sdof_closed, only: rect_pulse_response
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: n
    real(dp), intent(in) :: t(n), w0, t1, period
    real(dp), intent(out) :: z(n), v(n), a(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call rect_pulse_response(t, w0, t1, period, z, v, a, stat, errmsg)
end subroutine sp_rect_pulse_response

!> Response to an instantaneous acceleration impulse.
subroutine sp_impulse_response(n, t, jw, period, damping, z, v, a, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_sdof_closed, only: impulse_response
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: n
    real(dp), intent(in) :: t(n), jw, period, damping
    real(dp), intent(out) :: z(n), v(n), a(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call impulse_response(t, jw, period, damping, z, v, a, stat, errmsg)
end subroutine sp_impulse_response

!> Response to a pulse at times t.
subroutine sp_sdof_pulse_response(kind, params, period, damping, n, t, z, v, a, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_pulses, only: pulse_from_params, PULSE_NPARAM
    use seispulse_sdof_closed, only: sdof_pulse_response
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: kind, n
    real(dp), intent(in) :: params(PULSE_NPARAM), period, damping, t(n)
    real(dp), intent(out) :: z(n), v(n), a(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call sdof_pulse_response(pulse_from_params(kind, params), period, damping, t, z, v, a, &
                             stat, errmsg)
end subroutine sp_sdof_pulse_response

!> Peaks under a pulse: out = [z_max, t_z, v_max, t_v, a_max, t_a].
subroutine sp_sdof_pulse_peaks(kind, params, period, damping, out, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_pulses, only: pulse_from_params, PULSE_NPARAM
    use seispulse_sdof_closed, only: sdof_pulse_peaks
    implicit none
    !f2py threadsafe
    integer, intent(in) :: kind
    real(dp), intent(in) :: params(PULSE_NPARAM), period, damping
    real(dp), intent(out) :: out(6)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call sdof_pulse_peaks(pulse_from_params(kind, params), period, damping, out(1), out(2), &
                          out(3), out(4), out(5), out(6), stat, errmsg)
end subroutine sp_sdof_pulse_peaks

!> Spectra of a pulse, with the times of the maxima.
subroutine sp_sdof_pulse_spectrum(kind, params, n, periods, damping, sd, sv, sa, tsd, tsv, tsa, &
                                  stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_pulses, only: pulse_from_params, PULSE_NPARAM
    use seispulse_sdof_closed, only: sdof_pulse_spectrum
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: kind, n
    real(dp), intent(in) :: params(PULSE_NPARAM), periods(n), damping
    real(dp), intent(out) :: sd(n), sv(n), sa(n), tsd(n), tsv(n), tsa(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call sdof_pulse_spectrum(pulse_from_params(kind, params), periods, damping, sd, sv, sa, &
                             stat, errmsg, tsd, tsv, tsa)
end subroutine sp_sdof_pulse_spectrum

!> Peak |a_g| of a pulse and its time.
subroutine sp_pulse_peak_accel(kind, params, amax, tmax, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_pulses, only: pulse_from_params, pulse_peak_accel, PULSE_NPARAM
    implicit none
    !f2py threadsafe
    integer, intent(in) :: kind
    real(dp), intent(in) :: params(PULSE_NPARAM)
    real(dp), intent(out) :: amax, tmax
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call pulse_peak_accel(pulse_from_params(kind, params), amax, tmax, stat, errmsg)
end subroutine sp_pulse_peak_accel
