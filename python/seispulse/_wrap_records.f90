! f2py layer of seispulse.records (see _wrap.f90 for the conventions): plain external
! subroutines, explicit-shape arrays, integer flags, character(len=1024) errmsg (paths
! are long). No numerics here.
!
! A file of unknown length is read in two calls: sp_record_read reads it into the
! record held below and returns the sizes, sp_record_fetch copies the samples out and
! frees the record. The Python side makes both calls under one lock.

!> The record between sp_record_read and sp_record_fetch (f2py layer only).
module sp_records_held
    use seispulse_records, only: record_t
    implicit none
    private
    public :: held

    type(record_t), save :: held  !! the last record read, until fetched
end module sp_records_held

!> Read a record file. fmt: RECORD_* (0 auto); units: UNITS_* (0: not given, as the
!> file says or g); dt <= 0: not given. The record is kept for sp_record_fetch.
subroutine sp_record_read(path, fmt, units, dt, npts, dt_out, t0, fmt_out, pga, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_records, only: read_record
    use sp_records_held, only: held
    implicit none
    !f2py threadsafe
    character(len=*), intent(in) :: path
    integer, intent(in) :: fmt, units
    real(dp), intent(in) :: dt
    integer, intent(out) :: npts, fmt_out
    real(dp), intent(out) :: dt_out, t0, pga
    integer, intent(out) :: stat
    character(len=1024), intent(out) :: errmsg
    errmsg = ''
    if (units == 0) then
        call read_record(path, held, stat, errmsg, fmt=fmt, dt=dt)
    else
        call read_record(path, held, stat, errmsg, fmt=fmt, units=units, dt=dt)
    end if
    npts = held%npts
    dt_out = held%dt
    t0 = held%t0
    fmt_out = held%fmt
    pga = held%pga
end subroutine sp_record_read

!> Copy out the record of the last sp_record_read (n = its npts) and free it.
subroutine sp_record_fetch(n, accel, name, title)
    use seispulse_kinds, only: dp
    use sp_records_held, only: held
    implicit none
    !f2py threadsafe
    integer, intent(in) :: n
    real(dp), intent(out) :: accel(n)
    character(len=256), intent(out) :: name, title
    integer :: m
    accel(:) = 0.0_dp
    name = ''
    title = ''
    if (allocated(held%accel)) then
        m = min(n, size(held%accel))
        accel(1:m) = held%accel(1:m)
        deallocate(held%accel)
    end if
    if (allocated(held%name)) then
        name = held%name
        deallocate(held%name)
    end if
    if (allocated(held%title)) then
        title = held%title
        deallocate(held%title)
    end if
    held%npts = 0
end subroutine sp_record_fetch

!> PGA scale factor; slammer /= 0: SLAMMER's rounding of pga to 0.001 g.
subroutine sp_pga_scale_factor(pga, target_pga, slammer, factor, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_records, only: pga_scale_factor
    implicit none
    !f2py threadsafe
    real(dp), intent(in) :: pga, target_pga
    integer, intent(in) :: slammer
    real(dp), intent(out) :: factor
    integer, intent(out) :: stat
    character(len=1024), intent(out) :: errmsg
    errmsg = ''
    call pga_scale_factor(pga, target_pga, slammer /= 0, factor, stat, errmsg)
end subroutine sp_pga_scale_factor

!> Ground velocity (m/s) and displacement (m) of accel (g) at step dt (s).
subroutine sp_ground_motion(n, accel, dt, g, vel, disp, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_records, only: ground_motion
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: n
    real(dp), intent(in) :: accel(n)
    real(dp), intent(in) :: dt, g
    real(dp), intent(out) :: vel(n), disp(n)
    integer, intent(out) :: stat
    character(len=1024), intent(out) :: errmsg
    errmsg = ''
    call ground_motion(accel, dt, g, vel, disp, stat, errmsg)
end subroutine sp_ground_motion

!> The UNITS_* code of an acceleration unit name (accel_unit_code: the one vocabulary of
!> the library, the driver and Python).
subroutine sp_accel_unit_code(name, code, stat, errmsg)
    use seispulse_records, only: accel_unit_code
    implicit none
    !f2py threadsafe
    character(len=*), intent(in) :: name
    integer, intent(out) :: code
    integer, intent(out) :: stat
    character(len=1024), intent(out) :: errmsg
    errmsg = ''
    call accel_unit_code(name, code, stat, errmsg)
end subroutine sp_accel_unit_code

!> The factor from an acceleration unit to g (accel_unit_factor); g in m/s^2.
subroutine sp_accel_unit_factor(name, g, factor, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_records, only: accel_unit_factor
    implicit none
    !f2py threadsafe
    character(len=*), intent(in) :: name
    real(dp), intent(in) :: g
    real(dp), intent(out) :: factor
    integer, intent(out) :: stat
    character(len=1024), intent(out) :: errmsg
    errmsg = ''
    call accel_unit_factor(name, g, factor, stat, errmsg)
end subroutine sp_accel_unit_factor
