!> AFL++ harness for the record reader: reads the file named on the command line in
!> every format (auto, at2, slammer, column with dt = 0.01 s, time_accel) through
!> `read_record` and checks what the library promises (fuzz/README.md):
!>
!> - success: at least one sample, npts = size(accel), every sample finite (g), dt
!>   finite and > 0 (s), t0 finite (s), the format read is a concrete one;
!> - failure: stat is SEISPULSE_INVALID_INPUT or SEISPULSE_IO, the record is empty and
!>   the message is not blank and starts with the path.
!>
!> A broken promise calls C abort() (SIGABRT: a crash for AFL++). Built with coverage
!> instrumentation by fuzz/build.sh; in the meson build (no instrumentation) the same
!> program replays the corpus and the regression inputs (test/data/fuzz).
program fuzz_record
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use seispulse, only: dp, record_t, read_record, RECORD_AUTO, RECORD_AT2, RECORD_SLAMMER, &
                         RECORD_COLUMN, RECORD_TIME_ACCEL, SEISPULSE_SUCCESS, &
                         SEISPULSE_INVALID_INPUT, SEISPULSE_IO
    implicit none

    interface
        subroutine c_abort() bind(c, name='abort')
        end subroutine c_abort
    end interface

    integer, parameter :: formats(5) = [RECORD_AUTO, RECORD_AT2, RECORD_SLAMMER, RECORD_COLUMN, &
                                        RECORD_TIME_ACCEL]
    character(len=:), allocatable :: path
    character(len=4096) :: arg
    integer :: k, n, iarg

    do iarg = 1, command_argument_count()
        call get_command_argument(iarg, arg, n)
        if (n > len(arg)) then
            write(*, '(a)') 'fuzz_record: path too long'
            call c_abort()
        end if
        path = arg(1:n)
        do k = 1, size(formats)
            call check_one(path, formats(k))
        end do
    end do

contains

    subroutine check_one(path, fmt)
        character(len=*), intent(in) :: path
        integer, intent(in) :: fmt
        type(record_t) :: rec
        character(len=1024) :: msg
        integer :: stat
        msg = ''
        if (fmt == RECORD_COLUMN) then
            call read_record(path, rec, stat, msg, fmt=fmt, dt=0.01_dp)
        else
            call read_record(path, rec, stat, msg, fmt=fmt)
        end if
        if (stat == SEISPULSE_SUCCESS) then
            if (.not. allocated(rec%accel)) call broken('accel not allocated')
            if (rec%npts < 1 .or. rec%npts /= size(rec%accel)) call broken('npts')
            if (.not. all(ieee_is_finite(rec%accel))) call broken('a sample is not finite')
            if (.not. (ieee_is_finite(rec%dt) .and. rec%dt > 0.0_dp)) call broken('dt')
            if (.not. ieee_is_finite(rec%t0)) call broken('t0')
            if (rec%fmt == RECORD_AUTO) call broken('fmt AUTO after a read')
            if (fmt /= RECORD_AUTO .and. rec%fmt /= fmt) call broken('fmt differs')
        else
            if (stat /= SEISPULSE_INVALID_INPUT .and. stat /= SEISPULSE_IO) call broken('stat')
            if (rec%npts /= 0 .or. size(rec%accel) /= 0) call broken('samples after an error')
            if (len_trim(msg) == 0) call broken('empty message')
            if (index(msg, path) /= 1) call broken('the message does not start with the path')
        end if
    end subroutine check_one

    subroutine broken(what)
        character(len=*), intent(in) :: what
        write(*, '(a)') 'fuzz_record: broken promise: '//what
        call c_abort()
    end subroutine broken

end program fuzz_record
