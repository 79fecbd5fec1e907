! f2py layer of seispulse.sdof on records (see _wrap.f90 for the conventions): plain
! external subroutines, explicit-shape arrays, integer flags, character(len=256)
! errmsg. No numerics here.

!> Response history at the samples: z (m), z' (m/s), a_abs (g).
subroutine sp_sdof_response(n, accel, dt, period, damping, g, disp, vel, acc, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_sdof_sim, only: sdof_response
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: n
    real(dp), intent(in) :: accel(n), dt, period, damping, g
    real(dp), intent(out) :: disp(n), vel(n), acc(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    call sdof_response(accel, dt, period, damping, g, disp, vel, acc, stat, errmsg)
end subroutine sp_sdof_response

!> Spectra (period, damping): sd (m), sv (m/s), sa (g), psv (m/s), psa (g) and the
!> times of the true maxima (s). peaks: 1 exact, 2 samples; threads 0: default.
subroutine sp_sdof_spectrum(n, accel, dt, np, periods, nd, dampings, g, peaks, threads, &
                            sd, sv, sa, psv, psa, t_sd, t_sv, t_sa, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_sdof_sim, only: sdof_spectrum, pseudo_spectra
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n, np, nd
    integer, intent(in) :: n, np, nd
    real(dp), intent(in) :: accel(n), dt, periods(np), dampings(nd), g
    integer, intent(in) :: peaks, threads
    real(dp), intent(out) :: sd(np, nd), sv(np, nd), sa(np, nd), psv(np, nd), psa(np, nd)
    real(dp), intent(out) :: t_sd(np, nd), t_sv(np, nd), t_sa(np, nd)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    sd = 0.0_dp
    sv = 0.0_dp
    sa = 0.0_dp
    psv = 0.0_dp
    psa = 0.0_dp
    t_sd = 0.0_dp
    t_sv = 0.0_dp
    t_sa = 0.0_dp
    call sdof_spectrum(accel, dt, periods, dampings, g, sd, sv, sa, stat, errmsg, &
                       peaks=peaks, threads=threads, t_sd=t_sd, t_sv=t_sv, t_sa=t_sa)
    if (stat /= 0) return
    call pseudo_spectra(periods, sd, g, maxval(abs(accel)), psv, psa)
end subroutine sp_sdof_spectrum

!> Default number of OpenMP threads of a spectrum (1 without OpenMP).
subroutine sp_sdof_threads(n)
    use seispulse_sdof_sim, only: sdof_threads
    implicit none
    !f2py threadsafe
    integer, intent(out) :: n
    n = sdof_threads()
end subroutine sp_sdof_threads

!> Design envelope (period, spectrum) -> env, with the short-period plateau.
subroutine sp_design_envelope(np, ns, periods, spectra, plateau_below, env, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_sdof_sim, only: design_envelope
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: np, ns
    integer, intent(in) :: np, ns
    real(dp), intent(in) :: periods(np), spectra(np, ns), plateau_below
    real(dp), intent(out) :: env(np)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    env = 0.0_dp
    call design_envelope(periods, spectra, plateau_below, env, stat, errmsg)
end subroutine sp_design_envelope

!> Normalized shape PSA/PGA, the period of its peak and the peak.
subroutine sp_spectral_shape(np, periods, psa, pga, shape, t_peak, peak, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_sdof_sim, only: spectral_shape
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: np
    integer, intent(in) :: np
    real(dp), intent(in) :: periods(np), psa(np), pga
    real(dp), intent(out) :: shape(np), t_peak, peak
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    shape = 0.0_dp
    call spectral_shape(periods, psa, pga, shape, t_peak, peak, stat, errmsg)
end subroutine sp_spectral_shape
