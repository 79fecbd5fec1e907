!> Record files: every format on small fixture files written at run time (values known
!> from the text written), the strictness rules (file, line, what was expected), PGA
!> scaling and the exact ground velocity and displacement against closed forms.
module test_records
    use, intrinsic :: iso_c_binding, only: c_int
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, SEISPULSE_IO
    use seispulse_records, only: record_t, read_record, record_pga, pga_scale_factor, &
                                 ground_motion, record_format_name, record_units_name, &
                                 RECORD_AUTO, RECORD_AT2, RECORD_SLAMMER, RECORD_COLUMN, &
                                 RECORD_TIME_ACCEL, UNITS_G, UNITS_M_S2, UNITS_CM_S2, &
                                 STANDARD_GRAVITY, accel_unit_code, accel_unit_factor, &
                                 MAX_RECORD_SAMPLES, MAX_RECORD_BYTES
    use testing, only: test_error, unit_test, new_unittest, check
    implicit none
    private

    public :: collect_records

    character(len=*), parameter :: NL = new_line('a')
    character(len=*), parameter :: CRLF = achar(13)//new_line('a')

    interface
        !> POSIX getpid(): a unique fixture name per test process.
        function c_getpid() bind(c, name='getpid') result(pid)
            import :: c_int
            integer(c_int) :: pid
        end function c_getpid
    end interface

contains

    subroutine collect_records(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('AT2 NGA-West2 header: values, npts, dt, title', test_at2_west2), &
                 new_unittest('AT2 old NGA header, PEER detection, cm/s2 to g', test_at2_old), &
                 new_unittest('AT2 header variants and units in m/s2', test_at2_variants), &
                 new_unittest('AT2 NPTS against the data: fewer and more', test_at2_npts), &
                 new_unittest('AT2 bad header: DT, NPTS, velocity, short file', test_at2_header), &
                 new_unittest('AT2 units and dt given by the caller', test_at2_caller), &
                 new_unittest('non-numeric tokens name line and token', test_non_numeric), &
                 new_unittest('number forms are converted exactly', test_number_forms), &
                 new_unittest('SLAMMER CSV with BOM, CRLF, trailing commas', test_slammer), &
                 new_unittest('time/accel: comments, blanks, separators, t0', test_time_accel), &
                 new_unittest('time/accel: uniform grid, order, row width', test_time_errors), &
                 new_unittest('single column with and without dt', test_column), &
                 new_unittest('auto detection and explicit formats', test_detection), &
                 new_unittest('empty file, comments only, missing file', test_empty_missing), &
                 new_unittest('very long lines are read whole', test_long_lines), &
                 new_unittest('hostile files: NPTS, NUL, sizes, limits', test_hostile), &
                 new_unittest('a sparse file of 1 GiB is refused from its size', test_huge_file), &
                 new_unittest('bad arguments', test_bad_arguments), &
                 new_unittest('record_pga and the code names', test_pga_names), &
                 new_unittest('pga_scale_factor: exact and SLAMMER rounding', test_scale), &
                 new_unittest('ground_motion: linear acceleration, exact polynomials', &
                              test_ground_linear), &
                 new_unittest('ground_motion: errors', test_ground_errors), &
                 new_unittest('acceleration unit names: codes, factors, errors', test_unit_names)]
    end subroutine collect_records

    !> The one vocabulary of acceleration units: every name and case, the factor to g
    !> (1, 1/g, 1/(100 g) for a g of 9.81), unknown names and a bad g refused.
    subroutine test_unit_names(error)
        type(test_error), allocatable, intent(out) :: error
        character(len=8), parameter :: names(10) = [character(len=8) :: 'g', 'G', ' m/s2', &
            'M/S2', 'm/s^2', 'cm/s2', 'CM/S^2', 'gal', 'Gal ', 'GAL']
        integer, parameter :: codes(10) = [UNITS_G, UNITS_G, UNITS_M_S2, UNITS_M_S2, &
            UNITS_M_S2, UNITS_CM_S2, UNITS_CM_S2, UNITS_CM_S2, UNITS_CM_S2, UNITS_CM_S2]
        real(dp), parameter :: expect(3) = [1.0_dp, 1.0_dp / 9.81_dp, 1.0_dp / 981.0_dp]
        character(len=256) :: msg
        integer :: i, code, stat
        real(dp) :: factor
        do i = 1, size(names)
            call accel_unit_code(names(i), code, stat)
            call check(error, stat == SEISPULSE_SUCCESS .and. code == codes(i), trim(names(i)))
            if (allocated(error)) return
            call accel_unit_factor(names(i), 9.81_dp, factor, stat)
            call check(error, stat == SEISPULSE_SUCCESS, trim(names(i)))
            if (allocated(error)) return
            call check(error, factor, expect(codes(i)), rtol=1.0e-15_dp)
            if (allocated(error)) return
        end do
        msg = ''
        call accel_unit_code('ft/s2', code, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. code == 0 .and. trim(msg) == &
                   "'ft/s2': unknown acceleration unit (allowed: g, m/s2, m/s^2, cm/s2, " &
                   //"cm/s^2, gal)", trim(msg))
        if (allocated(error)) return
        msg = ''
        call accel_unit_factor('m/s2', 0.0_dp, factor, stat, msg)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'g = ') == 1, &
                   trim(msg))
    end subroutine test_unit_names

    ! ---------------------------------------------------------------- helpers

    !> A fixture path in $TMPDIR (or /tmp), unique to this process and tag.
    function tmp_file(tag) result(path)
        character(len=*), intent(in) :: tag
        character(len=:), allocatable :: path
        character(len=1024) :: dir
        character(len=24) :: pid
        integer :: n, st
        call get_environment_variable('TMPDIR', dir, n, st)
        if (st /= 0 .or. n == 0) dir = '/tmp'
        write(pid, '(i0)') c_getpid()
        path = trim(dir)//'/seispulse_records_'//trim(pid)//'_'//tag
    end function tmp_file

    !> Write `text` byte for byte (stream access: no record markers, no added newline).
    subroutine write_text(path, text)
        character(len=*), intent(in) :: path, text
        integer :: u
        open(newunit=u, file=path, access='stream', form='unformatted', status='replace', &
             action='write')
        write(u) text
        close(u)
    end subroutine write_text

    subroutine remove_file(path)
        character(len=*), intent(in) :: path
        integer :: u, ios
        open(newunit=u, file=path, status='old', iostat=ios)
        if (ios == 0) close(u, status='delete')
    end subroutine remove_file

    !> Write `text` to a fixture named `tag`, read it with the given options, delete it.
    subroutine read_text(text, tag, rec, stat, msg, path, fmt, units, dt, max_samples)
        character(len=*), intent(in) :: text, tag
        type(record_t), intent(out) :: rec
        integer, intent(out) :: stat
        character(len=*), intent(out) :: msg
        character(len=:), allocatable, intent(out) :: path
        integer, intent(in), optional :: fmt, units, max_samples
        real(dp), intent(in), optional :: dt
        path = tmp_file(tag)
        call write_text(path, text)
        msg = ''
        call read_record(path, rec, stat, msg, fmt=fmt, units=units, dt=dt, &
                         max_samples=max_samples)
        call remove_file(path)
    end subroutine read_text

    !> A successful read of `text`.
    subroutine read_ok(error, text, tag, rec, fmt, units, dt, max_samples)
        type(test_error), allocatable, intent(inout) :: error
        character(len=*), intent(in) :: text, tag
        type(record_t), intent(out) :: rec
        integer, intent(in), optional :: fmt, units, max_samples
        real(dp), intent(in), optional :: dt
        integer :: stat
        character(len=1024) :: msg
        character(len=:), allocatable :: path
        call read_text(text, tag, rec, stat, msg, path, fmt, units, dt, max_samples)
        call check(error, stat, SEISPULSE_SUCCESS, tag//': status ('//trim(msg)//')')
        if (allocated(error)) return
        call check(error, rec%npts, size(rec%accel), tag//': npts = size(accel)')
    end subroutine read_ok

    !> A failed read of `text`: status `code`, message starting with `<path>` + `head`
    !> (head = ':6: ' or ': ') and containing `part` (and `part2`).
    subroutine read_fails(error, text, tag, code, head, part, part2, fmt, units, dt, max_samples)
        type(test_error), allocatable, intent(inout) :: error
        character(len=*), intent(in) :: text, tag
        integer, intent(in) :: code
        character(len=*), intent(in) :: head, part
        character(len=*), intent(in), optional :: part2
        integer, intent(in), optional :: fmt, units, max_samples
        real(dp), intent(in), optional :: dt
        type(record_t) :: rec
        integer :: stat
        character(len=1024) :: msg
        character(len=:), allocatable :: path
        call read_text(text, tag, rec, stat, msg, path, fmt, units, dt, max_samples)
        call check(error, stat, code, tag//': status ('//trim(msg)//')')
        if (allocated(error)) return
        call check(error, index(msg, path//head) == 1, tag//": message should start with '" &
                   //path//head//"': "//trim(msg))
        if (allocated(error)) return
        call check(error, index(msg, part) > 0, tag//": message should contain '"//part &
                   //"': "//trim(msg))
        if (allocated(error)) return
        if (present(part2)) then
            call check(error, index(msg, part2) > 0, tag//": message should contain '" &
                       //part2//"': "//trim(msg))
            if (allocated(error)) return
        end if
        call check(error, rec%npts == 0 .and. size(rec%accel) == 0, tag//': no samples on error')
    end subroutine read_fails

    ! ---------------------------------------------------------------- AT2

    subroutine test_at2_west2(error)
        type(test_error), allocatable, intent(out) :: error
        type(record_t) :: rec
        character(len=*), parameter :: text = &
            'PEER NGA STRONG MOTION DATABASE RECORD'//NL// &
            'Imperial Valley-06, 10/15/1979, El Centro Array #6, 230'//NL// &
            'ACCELERATION TIME SERIES IN UNITS OF G'//NL// &
            'NPTS=     7, DT=   .0050 SEC'//NL// &
            '  .1000000E-01  -.2500000E+00   .3125000E-02  -.4000000E-03   .0000000E+00'//NL// &
            '  -.1234567E-02   .5000000E-01'//NL
        call read_ok(error, text, 'west2.AT2', rec)
        if (allocated(error)) return
        call check(error, rec%fmt, RECORD_AT2, 'fmt')
        if (allocated(error)) return
        call check(error, rec%npts, 7, 'npts')
        if (allocated(error)) return
        call check(error, rec%dt, 0.005_dp, rtol=0.0_dp, message='dt')
        if (allocated(error)) return
        call check(error, rec%accel, [0.01_dp, -0.25_dp, 0.003125_dp, -0.0004_dp, 0.0_dp, &
                                      -0.001234567_dp, 0.05_dp], rtol=0.0_dp, message='accel')
        if (allocated(error)) return
        call check(error, rec%pga, 0.25_dp, rtol=0.0_dp, message='pga')
        if (allocated(error)) return
        call check(error, rec%t0, 0.0_dp, rtol=0.0_dp, message='t0')
        if (allocated(error)) return
        call check(error, rec%title == 'Imperial Valley-06, 10/15/1979, El Centro Array #6, 230', &
                   'title: '//rec%title)
        if (allocated(error)) return
        call check(error, rec%name == 'seispulse_records_'//pid_str()//'_west2', 'name: '//rec%name)
    end subroutine test_at2_west2

    subroutine test_at2_old(error)
        type(test_error), allocatable, intent(out) :: error
        type(record_t) :: rec
        character(len=*), parameter :: text = &
            'PEER STRONG MOTION DATABASE RECORD. PROCESSING BY PACIFIC ENGINEERING.'//NL// &
            'LOMA PRIETA 10/18/89 00:05, GILROY ARRAY #1, 000'//NL// &
            'ACCELERATION TIME HISTORY IN UNITS OF CM/SEC/SEC'//NL// &
            '    5    .0100    NPTS, DT'//NL// &
            '  980.665  -490.3325  9.80665  0.0  -1961.33'//NL
        ! no .at2 extension: 'PEER' on line 1 decides
        call read_ok(error, text, 'old_nga.txt', rec)
        if (allocated(error)) return
        call check(error, rec%fmt, RECORD_AT2, 'fmt')
        if (allocated(error)) return
        call check(error, rec%npts, 5, 'npts')
        if (allocated(error)) return
        call check(error, rec%dt, 0.01_dp, rtol=0.0_dp, message='dt')
        if (allocated(error)) return
        ! 980.665 cm/s2 = 1 g exactly (to rounding)
        call check(error, rec%accel, [1.0_dp, -0.5_dp, 0.01_dp, 0.0_dp, -2.0_dp], rtol=3.0e-16_dp, &
                   message='accel in g')
        if (allocated(error)) return
        call check(error, rec%name == 'seispulse_records_'//pid_str()//'_old_nga', 'name')
    end subroutine test_at2_old

    subroutine test_at2_variants(error)
        type(test_error), allocatable, intent(out) :: error
        type(record_t) :: rec
        ! NPTS= n DT= dt without the comma, DT glued to SEC, m/s^2
        call read_ok(error, 'header'//NL//'title'//NL// &
                     'Acceleration in m/s^2'//NL//'NPTS= 3 DT= 0.02'//NL// &
                     '9.80665'//NL//NL//'-19.6133  4.903325'//NL, 'variant1.at2', rec)
        if (allocated(error)) return
        call check(error, rec%dt, 0.02_dp, rtol=0.0_dp, message='dt, no comma')
        if (allocated(error)) return
        call check(error, rec%accel, [1.0_dp, -2.0_dp, 0.5_dp], rtol=3.0e-16_dp, message='m/s2')
        if (allocated(error)) return
        call read_ok(error, 'x'//NL//'y'//NL//'ACCELERATION IN G'//NL// &
                     'NPTS=2, DT=.0050SEC'//CRLF//'1.5 -2.5'//CRLF, 'variant2.at2', rec)
        if (allocated(error)) return
        call check(error, rec%dt, 0.005_dp, rtol=0.0_dp, message='dt glued to SEC')
        if (allocated(error)) return
        call check(error, rec%accel, [1.5_dp, -2.5_dp], rtol=0.0_dp, message='CRLF AT2')
        if (allocated(error)) return
        ! no recognisable units: g assumed; 'gal' is cm/s2
        call read_ok(error, 'x'//NL//'y'//NL//'ACCELERATION'//NL//'NPTS= 1, DT= 1'//NL// &
                     '0.125', 'variant3.at2', rec)
        if (allocated(error)) return
        call check(error, rec%accel(1), 0.125_dp, rtol=0.0_dp, message='units assumed g')
        if (allocated(error)) return
        call read_ok(error, 'x'//NL//'y'//NL//'acceleration (gal)'//NL//'NPTS= 1, DT= 1'//NL// &
                     '1961.33', 'variant4.at2', rec)
        if (allocated(error)) return
        call check(error, rec%accel(1), 2.0_dp, rtol=3.0e-16_dp, message='gal')
    end subroutine test_at2_variants

    subroutine test_at2_npts(error)
        type(test_error), allocatable, intent(out) :: error
        character(len=*), parameter :: head = 'PEER NGA STRONG MOTION DATABASE RECORD'//NL// &
            'title'//NL//'ACCELERATION TIME SERIES IN UNITS OF G'//NL
        call read_fails(error, head//'NPTS=     6, DT=   .0050 SEC'//NL// &
                        '  .1E-01  .2E-01  .3E-01'//NL//'  .4E-01  .5E-01'//NL, &
                        'fewer.at2', SEISPULSE_INVALID_INPUT, ': ', 'NPTS = 6', 'only 5 values')
        if (allocated(error)) return
        call read_fails(error, head//'NPTS=     4, DT=   .0050 SEC'//NL// &
                        '  .1E-01  .2E-01  .3E-01'//NL//'  .4E-01  .5E-01'//NL, &
                        'more.at2', SEISPULSE_INVALID_INPUT, ':6: ', &
                        'more values than NPTS = 4', "'.5E-01'")
        if (allocated(error)) return
        call read_fails(error, head//'NPTS=     4, DT=   .0050 SEC'//NL, &
                        'nodata.at2', SEISPULSE_INVALID_INPUT, ': ', 'no data')
    end subroutine test_at2_npts

    subroutine test_at2_header(error)
        type(test_error), allocatable, intent(out) :: error
        character(len=*), parameter :: head = 'PEER NGA STRONG MOTION DATABASE RECORD'//NL// &
            'title'//NL//'ACCELERATION TIME SERIES IN UNITS OF G'//NL
        call read_fails(error, head//'NPTS=     6'//NL//'1 2 3 4 5 6'//NL, 'nodt.at2', &
                        SEISPULSE_INVALID_INPUT, ':4: ', 'DT missing', &
                        "'NPTS=  5590, DT=   .0050 SEC'")
        if (allocated(error)) return
        call read_fails(error, head//'DT= .005'//NL//'1 2 3 4 5 6'//NL, 'nonpts.at2', &
                        SEISPULSE_INVALID_INPUT, ':4: ', 'NPTS missing', &
                        "'  3999    .0100    NPTS, DT'")
        if (allocated(error)) return
        call read_fails(error, head//'NPTS=  6.5, DT= .005'//NL//'1 2 3 4 5 6'//NL, &
                        'badnpts.at2', SEISPULSE_INVALID_INPUT, ':4: ', &
                        "NPTS = '6.5' is not a positive integer")
        if (allocated(error)) return
        call read_fails(error, head//'NPTS=  6, DT= x.005'//NL//'1 2 3 4 5 6'//NL, &
                        'baddt.at2', SEISPULSE_INVALID_INPUT, ':4: ', &
                        "DT = 'x.005' is not a number")
        if (allocated(error)) return
        call read_fails(error, head//'NPTS=  6, DT= 0'//NL//'1 2 3 4 5 6'//NL, &
                        'zerodt.at2', SEISPULSE_INVALID_INPUT, ':4: ', 'must be > 0')
        if (allocated(error)) return
        call read_fails(error, head//'  6    NPTS, DT'//NL//'1 2 3 4 5 6'//NL, &
                        'oldone.at2', SEISPULSE_INVALID_INPUT, ':4: ', &
                        'two values expected before NPTS, DT')
        if (allocated(error)) return
        call read_fails(error, 'PEER NGA STRONG MOTION DATABASE RECORD'//NL//'title'//NL// &
                        'VELOCITY TIME SERIES IN UNITS OF CM/S'//NL// &
                        'NPTS=     2, DT=   .0050 SEC'//NL//'1 2'//NL, 'velocity.at2', &
                        SEISPULSE_INVALID_INPUT, ':3: ', 'not an acceleration record')
        if (allocated(error)) return
        call read_fails(error, 'PEER'//NL//'title'//NL//'TIME SERIES IN UNITS OF G'//NL// &
                        'NPTS=     2, DT=   .0050 SEC'//NL//'1 2'//NL, 'noaccel.at2', &
                        SEISPULSE_INVALID_INPUT, ':3: ', "expected the quantity and units")
        if (allocated(error)) return
        call read_fails(error, 'PEER NGA'//NL//'title'//NL, 'short.at2', &
                        SEISPULSE_INVALID_INPUT, ':3: ', 'the AT2 header has 4 lines')
    end subroutine test_at2_header

    subroutine test_at2_caller(error)
        type(test_error), allocatable, intent(out) :: error
        type(record_t) :: rec
        character(len=*), parameter :: cm = 'PEER'//NL//'t'//NL// &
            'ACCELERATION TIME SERIES IN UNITS OF CM/S/S'//NL//'NPTS= 2, DT= .01 SEC'//NL// &
            '490.3325 -980.665'//NL
        character(len=*), parameter :: none = 'PEER'//NL//'t'//NL// &
            'ACCELERATION TIME SERIES'//NL//'NPTS= 2, DT= .01 SEC'//NL//'4.903325 -9.80665'//NL
        ! the caller's units against the header's
        call read_fails(error, cm, 'units.at2', SEISPULSE_INVALID_INPUT, ':3: ', &
                        'the header gives the units as cm/s2', 'units = g was passed', &
                        units=UNITS_G)
        if (allocated(error)) return
        call read_ok(error, cm, 'units_same.at2', rec, units=UNITS_CM_S2)
        if (allocated(error)) return
        call check(error, rec%accel, [0.5_dp, -1.0_dp], rtol=3.0e-16_dp, message='cm/s2')
        if (allocated(error)) return
        ! header without units: the caller's units apply
        call read_ok(error, none, 'units_caller.at2', rec, units=UNITS_M_S2)
        if (allocated(error)) return
        call check(error, rec%accel, [0.5_dp, -1.0_dp], rtol=3.0e-16_dp, message='m/s2 given')
        if (allocated(error)) return
        ! dt: equal within 1e-6 relative -> the header's; otherwise an error
        call read_ok(error, cm, 'dt_close.at2', rec, dt=0.01_dp * (1.0_dp + 5.0e-7_dp))
        if (allocated(error)) return
        call check(error, rec%dt, 0.01_dp, rtol=0.0_dp, message="header's dt")
        if (allocated(error)) return
        call read_fails(error, cm, 'dt_far.at2', SEISPULSE_INVALID_INPUT, ':4: ', &
                        'DT = 0.01 s, but dt = 0.02 s was given', dt=0.02_dp)
    end subroutine test_at2_caller

    ! ---------------------------------------------------------------- values

    subroutine test_non_numeric(error)
        type(test_error), allocatable, intent(out) :: error
        character(len=*), parameter :: head = 'PEER'//NL//'title'//NL// &
            'ACCELERATION TIME SERIES IN UNITS OF G'//NL//'NPTS=     4, DT=   .0050 SEC'//NL// &
            '1.0 2.0'//NL
        character(len=12), parameter :: bad(10) = [character(len=12) :: 'abc', 'nan', 'inf', &
            '1.0.0', '1/2', '.', '1e', '-', '1.0e+', '0x10']
        integer :: k
        do k = 1, size(bad)
            call read_fails(error, head//'3.0 '//trim(bad(k))//NL, 'token.at2', &
                            SEISPULSE_INVALID_INPUT, ':6: ', &
                            "non-numeric value '"//trim(bad(k))//"'")
            if (allocated(error)) return
        end do
        ! a long token is quoted in part
        call read_fails(error, head//'3.0 '//repeat('x', 100)//NL, 'longtoken.at2', &
                        SEISPULSE_INVALID_INPUT, ':6: ', "'"//repeat('x', 40)//"...'")
        if (allocated(error)) return
        call read_fails(error, head//'3.0 1e400'//NL, 'range.at2', SEISPULSE_INVALID_INPUT, &
                        ':6: ', "value '1e400' is out of the range")
        if (allocated(error)) return
        ! a data line with an empty value
        call read_fails(error, '# c'//NL//'0.0,1.0'//NL//'0.1,,2.0'//NL, 'empty_value.csv', &
                        SEISPULSE_INVALID_INPUT, ':3: ', 'empty value')
        if (allocated(error)) return
        call read_fails(error, '# c'//NL//'0.0,1.0'//NL//'0.1,2.0,'//NL, 'trailing.csv', &
                        SEISPULSE_INVALID_INPUT, ':3: ', 'empty value')
    end subroutine test_non_numeric

    subroutine test_number_forms(error)
        type(test_error), allocatable, intent(out) :: error
        type(record_t) :: rec
        call read_ok(error, '.0050'//NL//'5.'//NL//'1D-3'//NL//'+2.5e+2'//NL//'-0'//NL// &
                     '1.2345678901234567890123'//NL//'1e-400'//NL//'-7.25E-310'//NL// &
                     '123456789012345678'//NL//'0.000000000000000000000000001'//NL// &
                     '  -3.5d0  '//NL, 'forms.txt', rec, dt=0.01_dp)
        if (allocated(error)) return
        call check(error, rec%fmt, RECORD_COLUMN, 'fmt')
        if (allocated(error)) return
        call check(error, rec%npts, 11, 'npts')
        if (allocated(error)) return
        call check(error, rec%accel(1:7), [0.005_dp, 5.0_dp, 0.001_dp, 250.0_dp, 0.0_dp, &
                                      1.2345678901234567890123_dp, 0.0_dp], rtol=0.0_dp, &
                   message='values')
        if (allocated(error)) return
        ! a subnormal (through the library conversion)
        call check(error, rec%accel(8) < 0.0_dp .and. rec%accel(8) > -7.26e-300_dp * 1.0e-10_dp &
                   .and. rec%accel(8) < -7.24e-300_dp * 1.0e-10_dp, 'subnormal')
        if (allocated(error)) return
        call check(error, rec%accel(9:), [123456789012345678.0_dp, 1.0e-27_dp, -3.5_dp], &
                   rtol=0.0_dp, message='long mantissa, large exponent')
        if (allocated(error)) return
        call check(error, sign(1.0_dp, rec%accel(5)) < 0.0_dp, '-0 keeps its sign')
    end subroutine test_number_forms

    ! ---------------------------------------------------------------- text formats

    subroutine test_slammer(error)
        type(test_error), allocatable, intent(out) :: error
        type(record_t) :: rec
        character(len=*), parameter :: text0 = '# Time Series: Test 1999 - ABC-090,'//CRLF// &
            "# Time (s),Acceleration (g's),"//CRLF//'0,0.5'//CRLF//'0.01, -0.25'//CRLF// &
            '0.02 ,1E-03'
        character(len=3 + len(text0)) :: text
        ! UTF-8 byte-order mark EF BB BF
        text = char(239)//char(187)//char(191)//text0
        call read_ok(error, text, 'slammer.csv', rec)
        if (allocated(error)) return
        call check(error, rec%fmt, RECORD_SLAMMER, 'fmt (auto)')
        if (allocated(error)) return
        call check(error, rec%npts, 3, 'npts')
        if (allocated(error)) return
        call check(error, rec%dt, 0.01_dp, rtol=0.0_dp, message='dt')
        if (allocated(error)) return
        call check(error, rec%accel, [0.5_dp, -0.25_dp, 0.001_dp], rtol=0.0_dp, message='accel')
        if (allocated(error)) return
        call check(error, rec%title == 'Time Series: Test 1999 - ABC-090', 'title: '//rec%title)
        if (allocated(error)) return
        call check(error, rec%name == 'seispulse_records_'//pid_str()//'_slammer', 'name')
        if (allocated(error)) return
        call read_ok(error, text, 'slammer2.csv', rec, fmt=RECORD_SLAMMER)
        if (allocated(error)) return
        call check(error, rec%fmt, RECORD_SLAMMER, 'fmt (explicit)')
        if (allocated(error)) return
        call check(error, rec%accel, [0.5_dp, -0.25_dp, 0.001_dp], rtol=0.0_dp, message='accel')
        if (allocated(error)) return
        ! explicit SLAMMER needs the two comment lines
        call read_fails(error, '# only one'//NL//'0,1'//NL//'1,2'//NL, 'slammer3.csv', &
                        SEISPULSE_INVALID_INPUT, ':2: ', "expected a '#' comment line", &
                        fmt=RECORD_SLAMMER)
    end subroutine test_slammer

    subroutine test_time_accel(error)
        type(test_error), allocatable, intent(out) :: error
        type(record_t) :: rec
        real(dp), parameter :: g = STANDARD_GRAVITY
        ! comments anywhere, blank lines, tabs and commas, a time origin of 1 s
        call read_ok(error, '# first comment'//NL//'# second'//NL//'# third'//NL//NL// &
                     '1.0'//achar(9)//'0.25'//NL//'1.1 , -0.5'//NL//'# inside'//NL// &
                     '   '//NL//'1.2 0.125'//NL//'1.3,1'//NL//'1.4  -1'//NL, &
                     'two columns.dat', rec)
        if (allocated(error)) return
        call check(error, rec%fmt, RECORD_TIME_ACCEL, 'fmt (3 comment lines: not SLAMMER)')
        if (allocated(error)) return
        call check(error, rec%npts, 5, 'npts')
        if (allocated(error)) return
        call check(error, rec%t0, 1.0_dp, rtol=0.0_dp, message='t0')
        if (allocated(error)) return
        call check(error, rec%dt, 0.1_dp, rtol=1.0e-15_dp, message='dt')
        if (allocated(error)) return
        call check(error, rec%accel, [0.25_dp, -0.5_dp, 0.125_dp, 1.0_dp, -1.0_dp], &
                   rtol=0.0_dp, message='accel')
        if (allocated(error)) return
        call check(error, rec%title == 'first comment', 'title')
        if (allocated(error)) return
        call check(error, rec%name == 'seispulse_records_'//pid_str()//'_two columns', &
                   'name with a space: '//rec%name)
        if (allocated(error)) return
        ! units in the file: m/s2 and cm/s2 converted to g
        call read_ok(error, '0 9.80665'//NL//'0.5 -4.903325'//NL, 'ms2.txt', rec, &
                     units=UNITS_M_S2)
        if (allocated(error)) return
        call check(error, rec%accel, [1.0_dp, -0.5_dp], rtol=3.0e-16_dp, message='m/s2')
        if (allocated(error)) return
        call check(error, rec%accel(1), 9.80665_dp / g, rtol=0.0_dp, message='m/s2 / g')
        if (allocated(error)) return
        call read_ok(error, '0 980.665'//NL//'0.5 -490.3325'//NL, 'cms2.txt', rec, &
                     units=UNITS_CM_S2)
        if (allocated(error)) return
        call check(error, rec%accel, [1.0_dp, -0.5_dp], rtol=3.0e-16_dp, message='cm/s2')
        if (allocated(error)) return
        call check(error, rec%dt, 0.5_dp, rtol=0.0_dp, message='dt of two rows')
        if (allocated(error)) return
        ! dt given: within 1e-6 relative it is accepted (the file's is kept)
        call read_ok(error, '0 1'//NL//'0.02 2'//NL//'0.04 3'//NL, 'dtok.txt', rec, &
                     dt=0.02_dp * (1.0_dp - 9.0e-7_dp))
        if (allocated(error)) return
        call check(error, rec%dt, 0.02_dp, rtol=1.0e-15_dp, message='dt kept')
        if (allocated(error)) return
        ! times with rounding noise well inside 1 % of dt are accepted
        call read_ok(error, '0 1'//NL//'0.0100004 2'//NL//'0.0199996 3'//NL//'0.03 4'//NL, &
                     'noise.txt', rec)
        if (allocated(error)) return
        call check(error, rec%dt, 0.01_dp, rtol=1.0e-15_dp, message='dt with noise')
    end subroutine test_time_accel

    subroutine test_time_errors(error)
        type(test_error), allocatable, intent(out) :: error
        ! off the grid at line 5 (t = 0.35 where 0.3 is expected, dt = 0.1)
        call read_fails(error, '# t a'//NL//'0.0 1'//NL//'0.1 2'//NL//'0.2 3'//NL// &
                        '0.35 4'//NL//'0.4 5'//NL//'0.5 6'//NL, 'grid.txt', &
                        SEISPULSE_INVALID_INPUT, ':5: ', 'time 0.35 is off the uniform', &
                        'expected 0.3 (dt = 0.1 s')
        if (allocated(error)) return
        ! 2 % of dt off: rejected (tolerance 1 %)
        call read_fails(error, '0.0 1'//NL//'0.102 2'//NL//'0.2 3'//NL, 'grid2.txt', &
                        SEISPULSE_INVALID_INPUT, ':2: ', 'time 0.102 is off the uniform')
        if (allocated(error)) return
        ! not increasing
        call read_fails(error, '0.0 1'//NL//'0.1 2'//NL//'0.1 3'//NL//'0.3 4'//NL, &
                        'order.txt', SEISPULSE_INVALID_INPUT, ':3: ', &
                        'time 0.1 is not after the previous time 0.1 (line 2)')
        if (allocated(error)) return
        ! a row of 3 values, of 1 value
        call read_fails(error, '0.0 1'//NL//'0.1 2 3'//NL, 'three.txt', &
                        SEISPULSE_INVALID_INPUT, ':2: ', &
                        'expected 2 values (time, acceleration), found 3')
        if (allocated(error)) return
        call read_fails(error, '0.0 1'//NL//'0.1'//NL, 'one.txt', &
                        SEISPULSE_INVALID_INPUT, ':2: ', 'found 1')
        if (allocated(error)) return
        ! one row only
        call read_fails(error, '# c'//NL//'0.0 1'//NL, 'onerow.txt', SEISPULSE_INVALID_INPUT, &
                        ': ', 'at least 2 rows')
        if (allocated(error)) return
        ! the caller's dt against the times
        call read_fails(error, '0 1'//NL//'0.02 2'//NL//'0.04 3'//NL, 'dtbad.txt', &
                        SEISPULSE_INVALID_INPUT, ': ', 'the times give dt = 0.02 s', &
                        'dt = 0.01 s was given', dt=0.01_dp)
    end subroutine test_time_errors

    subroutine test_column(error)
        type(test_error), allocatable, intent(out) :: error
        type(record_t) :: rec
        character(len=*), parameter :: text = '# accel in g'//NL//'0.5'//NL//NL//'-0.75'// &
            NL//'# note'//NL//'  1.25E-1  '//NL
        call read_ok(error, text, 'column.txt', rec, dt=0.02_dp)
        if (allocated(error)) return
        call check(error, rec%fmt, RECORD_COLUMN, 'fmt')
        if (allocated(error)) return
        call check(error, rec%dt, 0.02_dp, rtol=0.0_dp, message='dt')
        if (allocated(error)) return
        call check(error, rec%accel, [0.5_dp, -0.75_dp, 0.125_dp], rtol=0.0_dp, message='accel')
        if (allocated(error)) return
        call check(error, rec%title == 'accel in g', 'title')
        if (allocated(error)) return
        call read_fails(error, text, 'column_nodt.txt', SEISPULSE_INVALID_INPUT, ': ', &
                        'dt: a single-column file has no time step; give dt')
        if (allocated(error)) return
        call read_fails(error, text, 'column_dt0.txt', SEISPULSE_INVALID_INPUT, ': ', &
                        'dt: a single-column file has no time step', dt=0.0_dp)
        if (allocated(error)) return
        call read_fails(error, '1'//NL//'2 3'//NL, 'column_two.txt', SEISPULSE_INVALID_INPUT, &
                        ':2: ', 'expected 1 value', fmt=RECORD_COLUMN, dt=0.1_dp)
    end subroutine test_column

    subroutine test_detection(error)
        type(test_error), allocatable, intent(out) :: error
        type(record_t) :: rec
        ! NPTS on line 4 (no PEER, no .at2) -> AT2
        call read_ok(error, 'db'//NL//'title'//NL//'ACCELERATION IN G'//NL// &
                     'NPTS= 2, DT= 0.01'//NL//'1 2'//NL, 'npts4.txt', rec)
        if (allocated(error)) return
        call check(error, rec%fmt, RECORD_AT2, 'NPTS on line 4')
        if (allocated(error)) return
        ! extension in upper case with a dot in the directory-free name
        call read_ok(error, 'db'//NL//'t'//NL//'ACCELERATION'//NL//'2 0.01 NPTS, DT'//NL// &
                     '1 2'//NL, 'a.b.At2', rec)
        if (allocated(error)) return
        call check(error, rec%fmt, RECORD_AT2, '.At2')
        if (allocated(error)) return
        call check(error, rec%name == 'seispulse_records_'//pid_str()//'_a.b', 'name a.b')
        if (allocated(error)) return
        ! a PEER mention in a comment does not make an AT2
        call read_ok(error, '# PEER record converted'//NL//'# t, a'//NL//'0 1'//NL//'1 2'//NL, &
                     'peer_comment.csv', rec)
        if (allocated(error)) return
        call check(error, rec%fmt, RECORD_SLAMMER, 'two comment lines -> slammer')
        if (allocated(error)) return
        call read_ok(error, '0 1'//NL//'1 2'//NL, 'nocomment.csv', rec)
        if (allocated(error)) return
        call check(error, rec%fmt, RECORD_TIME_ACCEL, 'no comment -> time_accel')
        if (allocated(error)) return
        ! explicit time_accel on a SLAMMER-shaped file reports time_accel
        call read_ok(error, '# a'//NL//'# b'//NL//'0 1'//NL//'1 2'//NL, 'explicit.csv', rec, &
                     fmt=RECORD_TIME_ACCEL)
        if (allocated(error)) return
        call check(error, rec%fmt, RECORD_TIME_ACCEL, 'explicit time_accel')
        if (allocated(error)) return
        call read_fails(error, '# c'//NL//'0.0 1.0 2.0'//NL, 'three_auto.txt', &
                        SEISPULSE_INVALID_INPUT, ':2: ', 'expected 1 or 2 numbers', &
                        "found '0.0 1.0 2.0'")
        if (allocated(error)) return
        call read_fails(error, '# c'//NL//'time,accel'//NL//'0 1'//NL, 'header_auto.txt', &
                        SEISPULSE_INVALID_INPUT, ':2: ', 'expected 1 or 2 numbers')
        if (allocated(error)) return
        ! an explicit AT2 on a CSV: line 3 is not an AT2 header line
        call read_fails(error, '# a'//NL//'# b'//NL//'0 1'//NL//'1 2'//NL, 'csv_as_at2.csv', &
                        SEISPULSE_INVALID_INPUT, ':3: ', 'expected the quantity', &
                        fmt=RECORD_AT2)
    end subroutine test_detection

    subroutine test_empty_missing(error)
        type(test_error), allocatable, intent(out) :: error
        type(record_t) :: rec
        integer :: stat
        character(len=1024) :: msg
        character(len=:), allocatable :: path
        call read_fails(error, '', 'empty.txt', SEISPULSE_INVALID_INPUT, ': ', 'empty file')
        if (allocated(error)) return
        call read_fails(error, '# only'//NL//NL//'# comments'//NL, 'comments.txt', &
                        SEISPULSE_INVALID_INPUT, ': ', 'no data')
        if (allocated(error)) return
        call read_fails(error, '# only'//NL, 'comments_col.txt', SEISPULSE_INVALID_INPUT, &
                        ': ', 'no data', fmt=RECORD_COLUMN, dt=0.1_dp)
        if (allocated(error)) return
        path = tmp_file('does_not_exist.AT2')
        call remove_file(path)
        msg = ''
        call read_record(path, rec, stat, msg)
        call check(error, stat, SEISPULSE_IO, 'missing file: status')
        if (allocated(error)) return
        call check(error, index(msg, path//': cannot open: ') == 1, 'missing file: '//trim(msg))
        if (allocated(error)) return
        call check(error, rec%npts == 0 .and. size(rec%accel) == 0, 'missing file: no samples')
        if (allocated(error)) return
        ! a directory opens but cannot be read
        msg = ''
        call read_record('/', rec, stat, msg)
        call check(error, stat, SEISPULSE_IO, 'directory: status ('//trim(msg)//')')
    end subroutine test_empty_missing

    subroutine test_long_lines(error)
        type(test_error), allocatable, intent(out) :: error
        type(record_t) :: rec
        character(len=:), allocatable :: data
        integer, parameter :: n = 20000
        integer :: i, k, m
        character(len=16) :: buf
        real(dp), allocatable :: expected(:)
        ! all the values of an AT2 on one line of 320 kB, behind a comment of 100 kB in a
        ! text file
        allocate(expected(n))
        allocate(character(len=16 * n) :: data)
        k = 0
        do i = 1, n
            write(buf, '(i0)') i - n / 2
            m = len_trim(buf) + 7
            data(k + 1:k + m) = ' '//trim(buf)//'.5E-03'
            k = k + m
            expected(i) = (real(i - n / 2, dp) + sign(0.5_dp, real(i - n / 2, dp))) * 1.0e-3_dp
        end do
        data = data(1:k)
        call read_ok(error, 'PEER'//NL//'t'//NL//'ACCELERATION IN G'//NL// &
                     'NPTS= 20000, DT= 0.01'//NL//data//NL, 'long.at2', rec)
        if (allocated(error)) return
        call check(error, rec%npts, n, 'npts of the long line')
        if (allocated(error)) return
        call check(error, rec%accel, expected, rtol=4.0e-16_dp, message='long line values')
        if (allocated(error)) return
        call read_ok(error, '#'//repeat('c', 100000)//NL//'#'//NL//'0 1'//NL//'0.5 2'//NL, &
                     'longcomment.csv', rec)
        if (allocated(error)) return
        call check(error, rec%npts, 2, 'after a long comment')
        if (allocated(error)) return
        call check(error, len(rec%title), 100000, 'the title is the whole comment')
        if (allocated(error)) return
        ! a long bad line: the error names it and quotes the start
        call read_fails(error, '0 1'//NL//'0.5 2 '//repeat('9', 50000)//NL, 'longbad.txt', &
                        SEISPULSE_INVALID_INPUT, ':2: ', 'found 3')
    end subroutine test_long_lines

    !> Hostile or mistaken files: a huge, negative or zero-padded NPTS, NPTS far above the
    !> data, a NUL byte, a file ending inside a number, control bytes and a line of 1 MB
    !> in a message, the sample limit (MAX_RECORD_SAMPLES, or a lower max_samples) hit
    !> on the row past it in every format. Each error names the file and the line.
    subroutine test_hostile(error)
        type(test_error), allocatable, intent(out) :: error
        character(len=*), parameter :: head = 'PEER NGA STRONG MOTION DATABASE RECORD'//NL// &
            'title'//NL//'ACCELERATION TIME SERIES IN UNITS OF G'//NL
        type(record_t) :: rec
        integer :: stat
        character(len=1024) :: msg
        character(len=:), allocatable :: path
        ! the limits as documented (module notes of seispulse_record_reader)
        call check(error, MAX_RECORD_SAMPLES == 10000000 .and. MAX_RECORD_BYTES == 536870912, &
                   'MAX_RECORD_SAMPLES = 1e7, MAX_RECORD_BYTES = 512 MiB')
        if (allocated(error)) return
        ! a record of 1e8 samples announced: refused at line 4, nothing allocated for it
        call read_fails(error, head//'NPTS= 100000000, DT= .01 SEC'//NL//'1 2 3'//NL, &
                        'n1e8.at2', SEISPULSE_INVALID_INPUT, ':4: ', 'NPTS = 100000000', &
                        'MAX_RECORD_SAMPLES = 10000000')
        if (allocated(error)) return
        call read_fails(error, head//'NPTS= 99999999999999999999, DT= .01'//NL//'1'//NL, &
                        'n1e20.at2', SEISPULSE_INVALID_INPUT, ':4: ', &
                        "NPTS = '99999999999999999999'", 'more samples than a record may have')
        if (allocated(error)) return
        call read_fails(error, head//'  10000001    .0100    NPTS, DT'//NL//'1'//NL, &
                        'nold.at2', SEISPULSE_INVALID_INPUT, ':4: ', 'NPTS = 10000001')
        if (allocated(error)) return
        call read_fails(error, head//'NPTS= -5, DT= .01'//NL//'1'//NL, 'nneg.at2', &
                        SEISPULSE_INVALID_INPUT, ':4: ', "NPTS = '-5' is not a positive integer")
        if (allocated(error)) return
        ! leading zeros do not count towards the limit
        call read_ok(error, head//'NPTS= 00000000000000000003, DT= .01'//NL//'1 2 3'//NL, &
                     'nzeros.at2', rec)
        if (allocated(error)) return
        call check(error, rec%npts, 3, 'NPTS with leading zeros')
        if (allocated(error)) return
        ! NPTS far above the data (below the limit): the values are counted, not allocated
        call read_fails(error, head//'NPTS= 9999999, DT= .01'//NL//'1 2 3'//NL, 'nfar.at2', &
                        SEISPULSE_INVALID_INPUT, ': ', 'NPTS = 9999999', 'only 3 values (line 5)')
        if (allocated(error)) return
        ! max_samples: the row past the limit, in each format
        call read_fails(error, head//'NPTS= 6, DT= .01'//NL//'1 2 3 4 5 6'//NL, 'max.at2', &
                        SEISPULSE_INVALID_INPUT, ':4: ', 'NPTS = 6', 'max_samples = 5 samples', &
                        max_samples=5)
        if (allocated(error)) return
        call read_ok(error, head//'NPTS= 5, DT= .01'//NL//'1 2 3 4 5'//NL, 'max5.at2', rec, &
                     max_samples=5)
        if (allocated(error)) return
        call read_fails(error, '# c'//NL//'1'//NL//'2'//NL//NL//'3'//NL//'4'//NL, 'max.txt', &
                        SEISPULSE_INVALID_INPUT, ':6: ', 'a row of data', 'max_samples = 3', &
                        fmt=RECORD_COLUMN, dt=0.01_dp, max_samples=3)
        if (allocated(error)) return
        call read_fails(error, '# a'//NL//'# b'//NL//'0,1'//NL//'1,2'//NL//'2,3'//NL, &
                        'max.csv', SEISPULSE_INVALID_INPUT, ':5: ', 'max_samples = 2', &
                        max_samples=2)
        if (allocated(error)) return
        call read_ok(error, '0 1'//NL//'1 2'//NL, 'max2.dat', rec, max_samples=2)
        if (allocated(error)) return
        call check(error, rec%npts, 2, 'max_samples = npts is accepted')
        if (allocated(error)) return
        ! a bad max_samples is an argument error (message names the argument)
        call read_text('1'//NL, 'max0.txt', rec, stat, msg, path, dt=0.1_dp, max_samples=0)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'max_samples = 0: ' &
                   //'must be 1 to MAX_RECORD_SAMPLES = 10000000') == 1, 'max0: '//trim(msg))
        if (allocated(error)) return
        call read_text('1'//NL, 'max1e9.txt', rec, stat, msg, path, dt=0.1_dp, &
                       max_samples=MAX_RECORD_SAMPLES + 1)
        call check(error, stat == SEISPULSE_INVALID_INPUT .and. index(msg, 'max_samples = ' &
                   //'10000001: must be 1') == 1, 'max above the limit: '//trim(msg))
        if (allocated(error)) return
        ! NUL bytes: binary data, with the line and column of the first
        call read_fails(error, '0 1'//NL//'0.5 2'//achar(0)//NL, 'nul.txt', &
                        SEISPULSE_INVALID_INPUT, ':2: ', 'a NUL byte (column 6)', 'binary data')
        if (allocated(error)) return
        call read_fails(error, repeat(achar(0), 4096), 'zeros.at2', SEISPULSE_INVALID_INPUT, &
                        ':1: ', 'a NUL byte (column 1)')
        if (allocated(error)) return
        ! the file ends inside a number
        call read_fails(error, '1.0'//NL//'2.5e', 'midnum.txt', SEISPULSE_INVALID_INPUT, &
                        ':2: ', "'2.5e'", fmt=RECORD_COLUMN, dt=0.01_dp)
        if (allocated(error)) return
        call read_fails(error, head//'NPTS= 3, DT= .01'//NL//'1 2 -', 'midnum.at2', &
                        SEISPULSE_INVALID_INPUT, ':5: ', "'-'")
        if (allocated(error)) return
        ! control bytes in a quoted line are shown as \xNN
        call read_fails(error, '0 1 '//achar(27)//'[31m'//NL, 'esc.txt', &
                        SEISPULSE_INVALID_INPUT, ':1: ', "found '0 1 \x1B[31m'")
        if (allocated(error)) return
        ! a line of 1 MB: an error in bounded time, the message quotes 40 characters
        call read_text('0 1'//NL//'1 '//repeat('7', 1000000)//' 3'//NL, 'mb.txt', rec, stat, &
                       msg, path)
        call check(error, stat, SEISPULSE_INVALID_INPUT, '1 MB line: status')
        if (allocated(error)) return
        call check(error, index(msg, path//':2: ') == 1 .and. len_trim(msg) < len(path) + 200, &
                   '1 MB line: '//trim(msg))
    end subroutine test_hostile

    !> A sparse file of 1 GiB (one byte written at its end: no disk used) is refused from
    !> its size, before it is read: bounded time and memory.
    subroutine test_huge_file(error)
        type(test_error), allocatable, intent(out) :: error
        type(record_t) :: rec
        integer :: stat, u, ios
        character(len=1024) :: msg
        character(len=:), allocatable :: path
        path = tmp_file('huge.txt')
        open(newunit=u, file=path, access='stream', form='unformatted', status='replace', &
             action='write', iostat=ios)
        if (ios == 0) write(u, pos=1073741824, iostat=ios) NL
        if (ios == 0) close(u, iostat=ios)
        call check(error, ios == 0, 'cannot write the sparse fixture '//path)
        if (allocated(error)) then
            call remove_file(path)
            return
        end if
        msg = ''
        call read_record(path, rec, stat, msg)
        call remove_file(path)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'huge file: status ('//trim(msg)//')')
        if (allocated(error)) return
        call check(error, index(msg, path//': the file has 1073741824 bytes') == 1 .and. &
                   index(msg, 'MAX_RECORD_BYTES = 536870912') > 0, 'huge file: '//trim(msg))
    end subroutine test_huge_file

    subroutine test_bad_arguments(error)
        type(test_error), allocatable, intent(out) :: error
        type(record_t) :: rec
        integer :: stat
        character(len=1024) :: msg
        msg = ''
        call read_record('whatever.AT2', rec, stat, msg, fmt=7)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'fmt = 7')
        if (allocated(error)) return
        call check(error, index(msg, 'fmt = 7: must be') == 1, 'fmt message: '//trim(msg))
        if (allocated(error)) return
        call read_record('whatever.AT2', rec, stat, msg, units=0)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'units = 0')
        if (allocated(error)) return
        call check(error, index(msg, 'units = 0: must be') == 1, 'units message: '//trim(msg))
        if (allocated(error)) return
        call read_record('whatever.AT2', rec, stat, msg, dt=ieee_value(1.0_dp, ieee_quiet_nan))
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'dt = NaN')
        if (allocated(error)) return
        call check(error, index(msg, 'dt = NaN: must be') == 1, 'dt message: '//trim(msg))
        if (allocated(error)) return
        ! no errmsg argument: the status alone
        call read_record('/nonexistent/seispulse/x.csv', rec, stat)
        call check(error, stat, SEISPULSE_IO, 'no errmsg')
    end subroutine test_bad_arguments

    ! ---------------------------------------------------------------- PGA, names

    subroutine test_pga_names(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: empty(0)
        call check(error, record_pga(empty), 0.0_dp, rtol=0.0_dp, message='empty')
        if (allocated(error)) return
        call check(error, record_pga([0.5_dp, -3.0_dp, 2.0_dp]), 3.0_dp, rtol=0.0_dp, &
                   message='max |a|')
        if (allocated(error)) return
        call check(error, record_format_name(RECORD_AUTO) == 'auto' .and. &
                   record_format_name(RECORD_AT2) == 'at2' .and. &
                   record_format_name(RECORD_SLAMMER) == 'slammer' .and. &
                   record_format_name(RECORD_COLUMN) == 'column' .and. &
                   record_format_name(RECORD_TIME_ACCEL) == 'time_accel' .and. &
                   record_format_name(9) == 'unknown', 'format names')
        if (allocated(error)) return
        call check(error, record_units_name(UNITS_G) == 'g' .and. &
                   record_units_name(UNITS_M_S2) == 'm/s2' .and. &
                   record_units_name(UNITS_CM_S2) == 'cm/s2' .and. &
                   record_units_name(0) == 'unknown', 'units names')
    end subroutine test_pga_names

    subroutine test_scale(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: f
        integer :: stat
        character(len=256) :: msg
        call pga_scale_factor(0.184882_dp, 0.3_dp, .false., f, stat, msg)
        call check(error, stat, SEISPULSE_SUCCESS, 'exact: status')
        if (allocated(error)) return
        call check(error, f, 0.3_dp / 0.184882_dp, rtol=0.0_dp, message='exact')
        if (allocated(error)) return
        ! SLAMMER: 0.184882 -> 0.185
        call pga_scale_factor(0.184882_dp, 0.3_dp, .true., f, stat, msg)
        call check(error, f, 0.3_dp / 0.185_dp, rtol=2.0e-16_dp, message='slammer 0.185')
        if (allocated(error)) return
        ! half away from zero: 0.4375 -> 0.438 (437.5 is exact in binary)
        call pga_scale_factor(0.4375_dp, 1.0_dp, .true., f, stat, msg)
        call check(error, f, 1.0_dp / 0.438_dp, rtol=2.0e-16_dp, message='slammer 0.4375')
        if (allocated(error)) return
        call pga_scale_factor(0.0016_dp, 0.5_dp, .true., f, stat, msg)
        call check(error, f, 0.5_dp / 0.002_dp, rtol=2.0e-16_dp, message='slammer 0.0016')
        if (allocated(error)) return
        msg = ''
        call pga_scale_factor(0.0004_dp, 0.3_dp, .true., f, stat, msg)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'rounds to 0')
        if (allocated(error)) return
        call check(error, index(msg, 'pga = 0.0004: rounds to 0.000 g') == 1, trim(msg))
        if (allocated(error)) return
        call pga_scale_factor(0.0004_dp, 0.3_dp, .false., f, stat, msg)
        call check(error, f, 750.0_dp, rtol=2.0e-16_dp, message='exact small pga')
        if (allocated(error)) return
        call pga_scale_factor(0.0_dp, 0.3_dp, .false., f, stat, msg)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'pga = 0')
        if (allocated(error)) return
        call check(error, index(msg, 'pga = 0.0: must be') == 1, trim(msg))
        if (allocated(error)) return
        call pga_scale_factor(0.2_dp, ieee_value(1.0_dp, ieee_quiet_nan), .false., f, stat, msg)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'target NaN')
        if (allocated(error)) return
        call check(error, index(msg, 'target_pga = NaN: must be') == 1, trim(msg))
        if (allocated(error)) return
        call pga_scale_factor(0.2_dp, -1.0_dp, .true., f, stat, msg)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'target < 0')
    end subroutine test_scale

    ! ---------------------------------------------------------------- ground motion

    subroutine test_ground_linear(error)
        type(test_error), allocatable, intent(out) :: error
        integer, parameter :: n = 101
        real(dp), parameter :: dt = 0.01_dp, g = 9.81_dp, c0 = 0.3_dp, c1 = -0.8_dp
        real(dp) :: a(n), t(n), v(n), d(n)
        integer :: i, stat
        do i = 1, n
            t(i) = real(i - 1, dp) * dt
        end do
        ! a(t) = c0 + c1 t, linear between samples: v and d are exact polynomials
        a = c0 + c1 * t
        call ground_motion(a, dt, g, v, d, stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'status')
        if (allocated(error)) return
        call check(error, v, g * (c0 * t + c1 * t**2 / 2.0_dp), rtol=1.0e-13_dp, &
                   atol=1.0e-15_dp, message='velocity')
        if (allocated(error)) return
        call check(error, d, g * (c0 * t**2 / 2.0_dp + c1 * t**3 / 6.0_dp), rtol=1.0e-13_dp, &
                   atol=1.0e-16_dp, message='displacement')
        if (allocated(error)) return
        ! constant acceleration: d = g a t^2 / 2
        a = 0.25_dp
        call ground_motion(a, dt, g, v, d, stat)
        call check(error, v, g * 0.25_dp * t, rtol=1.0e-13_dp, message='constant: v')
        if (allocated(error)) return
        call check(error, d, g * 0.25_dp * t**2 / 2.0_dp, rtol=1.0e-13_dp, &
                   message='constant: d')
        if (allocated(error)) return
        ! a triangle 0 -> 1 -> 0 over 2 steps (dt = 1, g = 1): v = 1/2, 1; d = 1/6, 1
        call ground_motion([0.0_dp, 1.0_dp, 0.0_dp], 1.0_dp, 1.0_dp, v(1:3), d(1:3), stat)
        call check(error, v(1:3), [0.0_dp, 0.5_dp, 1.0_dp], rtol=1.0e-15_dp, message='triangle v')
        if (allocated(error)) return
        call check(error, d(1:3), [0.0_dp, 1.0_dp / 6.0_dp, 1.0_dp], rtol=1.0e-15_dp, &
                   message='triangle d')
        if (allocated(error)) return
        ! one sample: at rest
        call ground_motion([2.0_dp], 0.1_dp, g, v(1:1), d(1:1), stat)
        call check(error, stat, SEISPULSE_SUCCESS, 'one sample: status')
        if (allocated(error)) return
        call check(error, [v(1), d(1)], [0.0_dp, 0.0_dp], atol=0.0_dp, message='one sample')
    end subroutine test_ground_linear

    subroutine test_ground_errors(error)
        type(test_error), allocatable, intent(out) :: error
        real(dp) :: v(3), d(3), v2(2)
        integer :: stat
        character(len=256) :: msg
        call ground_motion([1.0_dp, 2.0_dp, 3.0_dp], 0.1_dp, 9.81_dp, v2, d, stat, msg)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'vel size')
        if (allocated(error)) return
        call check(error, index(msg, 'vel: size 2, must be the size of accel (3)') == 1, trim(msg))
        if (allocated(error)) return
        call ground_motion([1.0_dp, 2.0_dp, 3.0_dp], 0.0_dp, 9.81_dp, v, d, stat, msg)
        call check(error, index(msg, 'dt = 0.0: must be') == 1, trim(msg))
        if (allocated(error)) return
        call ground_motion([1.0_dp, 2.0_dp, 3.0_dp], 0.1_dp, ieee_value(1.0_dp, ieee_quiet_nan), &
                           v, d, stat, msg)
        call check(error, index(msg, 'g = NaN: must be') == 1, trim(msg))
        if (allocated(error)) return
        call ground_motion([1.0_dp, ieee_value(1.0_dp, ieee_quiet_nan), 3.0_dp], 0.1_dp, 9.81_dp, &
                           v, d, stat, msg)
        call check(error, stat, SEISPULSE_INVALID_INPUT, 'NaN sample')
        if (allocated(error)) return
        call check(error, index(msg, 'accel(2) = NaN: must be a finite number') == 1, trim(msg))
    end subroutine test_ground_errors

    function pid_str() result(s)
        character(len=:), allocatable :: s
        character(len=24) :: buf
        write(buf, '(i0)') c_getpid()
        s = trim(buf)
    end function pid_str

end module test_records
