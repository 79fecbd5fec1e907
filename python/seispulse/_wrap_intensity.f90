! f2py layer of seispulse.records' intensity measures (see _wrap.f90 for the
! conventions): plain external subroutines, explicit-shape arrays, no numerics.

!> Intensity measures of accel (g) at step dt (s): PGA (g), PGV (m/s), PGD (m), Arias
!> intensity (m/s), CAV (m/s), D5-75, D5-95, t5, t75, t95 and Tm (s).
subroutine sp_record_intensity(n, accel, dt, g, pga, pgv, pgd, arias, cav, d5_75, d5_95, &
                               t5, t75, t95, tm, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_intensity, only: intensity_t, record_intensity
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: n
    real(dp), intent(in) :: accel(n)
    real(dp), intent(in) :: dt, g
    real(dp), intent(out) :: pga, pgv, pgd, arias, cav, d5_75, d5_95, t5, t75, t95, tm
    integer, intent(out) :: stat
    character(len=1024), intent(out) :: errmsg
    type(intensity_t) :: im
    errmsg = ''
    call record_intensity(accel, dt, g, im, stat, errmsg)
    pga = im%pga
    pgv = im%pgv
    pgd = im%pgd
    arias = im%arias
    cav = im%cav
    d5_75 = im%d5_75
    d5_95 = im%d5_95
    t5 = im%t5
    t75 = im%t75
    t95 = im%t95
    tm = im%tm
end subroutine sp_record_intensity

!> Spectral pseudo-acceleration (g) of accel (g) at step dt (s) for the oscillator of
!> period (s, 0: PGA) and damping ratio damping.
subroutine sp_spectral_acceleration(n, accel, dt, period, damping, g, sa, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_intensity, only: spectral_acceleration
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: n
    real(dp), intent(in) :: accel(n)
    real(dp), intent(in) :: dt, period, damping, g
    real(dp), intent(out) :: sa
    integer, intent(out) :: stat
    character(len=1024), intent(out) :: errmsg
    errmsg = ''
    call spectral_acceleration(accel, dt, period, damping, g, sa, stat, errmsg)
end subroutine sp_spectral_acceleration
