!> Accelerograms. The record (samples in g at a constant time step), reading it from a
!> file, PGA scaling and ground velocity/displacement.
!>
!> Formats (`read_record`; the files are parsed by seispulse_record_reader, whose
!> notes describe each format, the detection of `RECORD_AUTO` and the messages):
!> `RECORD_AT2` (PEER NGA `.AT2`), `RECORD_SLAMMER` (SLAMMER / pySLAMMER CSV),
!> `RECORD_TIME_ACCEL` (two columns, time and acceleration), `RECORD_COLUMN` (one
!> value per line, dt from the caller). Numbers are read correctly rounded, bitwise
!> equal to what numpy or C would read (seispulse_number_reader).
!>
!> Accelerations are stored in g: values in m/s^2 are divided by STANDARD_GRAVITY,
!> values in cm/s^2 by 100 STANDARD_GRAVITY.
module seispulse_records
    use, intrinsic :: ieee_arithmetic, only: ieee_is_finite
    use seispulse_kinds, only: dp
    use seispulse_checks, only: finite_positive
    use seispulse_format, only: num_str, int_str, upper, quote, code_of
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, set_error
    use seispulse_record_reader, only: read_record_file, base_name, record_format_name, &
                                       record_units_name, RECORD_AUTO, RECORD_AT2, &
                                       RECORD_SLAMMER, RECORD_COLUMN, RECORD_TIME_ACCEL, &
                                       UNITS_G, UNITS_M_S2, UNITS_CM_S2, MAX_RECORD_SAMPLES, &
                                       MAX_RECORD_BYTES
    implicit none
    private

    public :: record_t, read_record, record_pga, pga_scale_factor, ground_motion, &
              record_format_name, record_units_name
    public :: RECORD_AUTO, RECORD_AT2, RECORD_SLAMMER, RECORD_COLUMN, RECORD_TIME_ACCEL
    public :: UNITS_G, UNITS_M_S2, UNITS_CM_S2, STANDARD_GRAVITY
    public :: MAX_RECORD_SAMPLES, MAX_RECORD_BYTES
    public :: accel_unit_code, accel_unit_factor, ACCEL_UNIT_NAMES

    real(dp), parameter :: STANDARD_GRAVITY = 9.80665_dp  !! m/s^2, for unit conversion

    !> The acceleration units accepted by name, everywhere (records, pulses, the driver,
    !> Python): the one vocabulary. Matched without regard to case or surrounding blanks.
    character(len=6), parameter :: ACCEL_UNIT_NAMES(6) = [character(len=6) :: 'g', 'm/s2', &
        'm/s^2', 'cm/s2', 'cm/s^2', 'gal']
    !> The UNITS_* code of each name of ACCEL_UNIT_NAMES.
    integer, parameter :: ACCEL_UNIT_CODES(6) = [UNITS_G, UNITS_M_S2, UNITS_M_S2, UNITS_CM_S2, &
        UNITS_CM_S2, UNITS_CM_S2]

    !> An accelerogram sampled at a constant time step, in g.
    type :: record_t
        real(dp), allocatable :: accel(:)      !! ground acceleration (g), accel(i) at t = (i-1) dt
        real(dp) :: dt = 0.0_dp                !! time step (s)
        integer :: npts = 0                    !! number of samples = size(accel)
        real(dp) :: pga = 0.0_dp               !! max |accel| (g)
        real(dp) :: t0 = 0.0_dp                !! time of the first sample in the file (s; 0
                                               !! unless a time column says otherwise)
        integer :: fmt = RECORD_AUTO           !! the format actually read (never AUTO after a read)
        character(len=:), allocatable :: name  !! file name without directory and extension
        character(len=:), allocatable :: title !! line 2 of the header (AT2); text formats: the
                                               !! first comment line without '#'; else ''
    end type record_t

contains

    ! ------------------------------------------------------------------------------
    ! Public API
    ! ------------------------------------------------------------------------------

    !> Read an accelerogram file (formats in the module notes of seispulse_record_reader)
    !> into `rec`, in g.
    !>
    !> stat = SEISPULSE_IO when the file cannot be opened or read
    !> ("<path>: cannot open: <system message>"), SEISPULSE_INVALID_INPUT for a
    !> malformed file or a bad argument (the message names the file and the line, what
    !> was expected and what was found). On error `rec` holds no samples (npts = 0).
    !>
    !> Limits (seispulse_record_reader's notes give the reasoning): at most
    !> MAX_RECORD_SAMPLES = 10 000 000 samples (or `max_samples`) and a file of at most
    !> MAX_RECORD_BYTES = 512 MiB; a NUL byte is an error. Beyond them the error comes in
    !> bounded time and memory and names the file and the line.
    subroutine read_record(path, rec, stat, errmsg, fmt, units, dt, max_samples)
        character(len=*), intent(in) :: path                  !! the file
        type(record_t), intent(out) :: rec                    !! the record read
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer, intent(in), optional :: fmt     !! RECORD_*, default RECORD_AUTO
        integer, intent(in), optional :: units   !! UNITS_* of the values in the file, default
                                                 !! UNITS_G (AT2: the units of header line 3)
        real(dp), intent(in), optional :: dt     !! time step (s); required for RECORD_COLUMN;
                                                 !! <= 0 or absent = not given
        integer, intent(in), optional :: max_samples  !! the most samples accepted, 1 to
                                                      !! MAX_RECORD_SAMPLES (the default)
        integer :: want, units_in, units_read, fmt_read
        real(dp) :: dt_in

        stat = SEISPULSE_SUCCESS
        allocate(rec%accel(0))
        rec%name = base_name(path)
        rec%title = ''

        want = RECORD_AUTO
        if (present(fmt)) want = fmt
        if (want < RECORD_AUTO .or. want > RECORD_TIME_ACCEL) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'fmt = '//int_str(want) &
                           //': must be RECORD_AUTO (0), RECORD_AT2 (1), RECORD_SLAMMER (2), ' &
                           //'RECORD_COLUMN (3) or RECORD_TIME_ACCEL (4)')
            return
        end if
        units_in = 0
        if (present(units)) then
            if (units < UNITS_G .or. units > UNITS_CM_S2) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'units = ' &
                               //int_str(units)//': must be UNITS_G (1), UNITS_M_S2 (2) or ' &
                               //'UNITS_CM_S2 (3)')
                return
            end if
            units_in = units
        end if
        dt_in = 0.0_dp
        if (present(dt)) then
            if (.not. ieee_is_finite(dt)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'dt = '//num_str(dt) &
                               //': must be a finite time step > 0 (s), or <= 0 for none')
                return
            end if
            dt_in = max(dt, 0.0_dp)
        end if

        call read_record_file(path, want, units_in, dt_in, rec%accel, units_read, rec%dt, rec%t0, &
                              rec%title, fmt_read, stat, errmsg, max_samples)
        if (stat == SEISPULSE_SUCCESS) call to_g(rec%accel, units_read, path, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) then
            rec%npts = 0
            rec%dt = 0.0_dp
            rec%t0 = 0.0_dp
            rec%fmt = RECORD_AUTO
            if (allocated(rec%accel)) deallocate(rec%accel)
            allocate(rec%accel(0))
            return
        end if
        rec%fmt = fmt_read
        rec%npts = size(rec%accel)
        rec%pga = record_pga(rec%accel)
    end subroutine read_record

    !> Peak ground acceleration: max |accel| (0 for an empty array), in the units of accel.
    pure real(dp) function record_pga(accel)
        real(dp), intent(in) :: accel(:)  !! the samples
        integer :: i
        record_pga = 0.0_dp
        do i = 1, size(accel)
            record_pga = max(record_pga, abs(accel(i)))
        end do
    end function record_pga

    !> Scale factor that brings a record of PGA `pga` to `target_pga`.
    !>
    !> factor = target_pga / pga, or with `slammer_rounding` SLAMMER's convention
    !> target_pga / (nint(1000 pga) / 1000): the record's PGA rounded to 3 decimals
    !> (half away from zero), as SLAMMER displays and uses it.
    subroutine pga_scale_factor(pga, target_pga, slammer_rounding, factor, stat, errmsg)
        real(dp), intent(in) :: pga                           !! PGA of the record (g), > 0
        real(dp), intent(in) :: target_pga                    !! wanted PGA (g), > 0
        logical, intent(in) :: slammer_rounding               !! round pga to 0.001 first
        real(dp), intent(out) :: factor                       !! the scale factor
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        real(dp) :: p
        factor = 0.0_dp
        stat = SEISPULSE_SUCCESS
        if (.not. finite_positive(pga)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'pga = '//num_str(pga) &
                           //': must be a finite number > 0 (g)')
            return
        end if
        if (.not. finite_positive(target_pga)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'target_pga = ' &
                           //num_str(target_pga)//': must be a finite number > 0 (g)')
            return
        end if
        p = pga
        if (slammer_rounding) then
            ! anint, not nint: no integer overflow for a huge pga
            p = anint(pga * 1000.0_dp) / 1000.0_dp
            if (.not. p > 0.0_dp) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'pga = '//num_str(pga) &
                               //': rounds to 0.000 g, SLAMMER scaling impossible')
                return
            end if
        end if
        factor = target_pga / p
        if (.not. ieee_is_finite(factor)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'target_pga = ' &
                           //num_str(target_pga)//': target_pga / pga overflows')
            factor = 0.0_dp
        end if
    end subroutine pga_scale_factor

    !> Ground velocity and displacement of a record, exact for an acceleration that is
    !> linear between samples and at rest at the first sample (v = d = 0 there):
    !>     vel(i+1) = vel(i) + g dt (a_i + a_{i+1}) / 2
    !>     disp(i+1) = disp(i) + vel(i) dt + g dt^2 (2 a_i + a_{i+1}) / 6
    !> With accel in g and g in m/s^2, vel is in m/s and disp in m.
    subroutine ground_motion(accel, dt, g, vel, disp, stat, errmsg)
        real(dp), intent(in) :: accel(:)                      !! ground acceleration (g)
        real(dp), intent(in) :: dt                            !! time step (s), > 0
        real(dp), intent(in) :: g                             !! gravity (m/s^2), > 0
        real(dp), intent(out) :: vel(:)                       !! velocity (m/s), size(accel)
        real(dp), intent(out) :: disp(:)                      !! displacement (m), size(accel)
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer :: i, n
        real(dp) :: h1, h2
        stat = SEISPULSE_SUCCESS
        n = size(accel)
        if (size(vel) /= n) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'vel: size '//int_str(size(vel)) &
                           //', must be the size of accel ('//int_str(n)//')')
            return
        end if
        if (size(disp) /= n) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'disp: size ' &
                           //int_str(size(disp))//', must be the size of accel (' &
                           //int_str(n)//')')
            return
        end if
        vel(:) = 0.0_dp
        disp(:) = 0.0_dp
        if (.not. finite_positive(dt)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'dt = '//num_str(dt) &
                           //': must be a finite time step > 0 (s)')
            return
        end if
        if (.not. finite_positive(g)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'g = '//num_str(g) &
                           //': must be a finite number > 0 (m/s^2)')
            return
        end if
        do i = 1, n
            if (.not. ieee_is_finite(accel(i))) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'accel('//int_str(i) &
                               //') = '//num_str(accel(i))//': must be a finite number')
                return
            end if
        end do
        h1 = g * dt / 2.0_dp
        h2 = g * dt * dt / 6.0_dp
        do i = 1, n - 1
            vel(i + 1) = vel(i) + h1 * (accel(i) + accel(i + 1))
            disp(i + 1) = disp(i) + vel(i) * dt + h2 * (2.0_dp * accel(i) + accel(i + 1))
        end do
        if (n > 0) then
            if (.not. (ieee_is_finite(vel(n)) .and. ieee_is_finite(disp(n)))) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'accel, dt, g: the ' &
                               //'velocity or displacement overflows')
            end if
        end if
    end subroutine ground_motion

    !> The UNITS_* code of an acceleration unit named as in ACCEL_UNIT_NAMES ('g', 'm/s2',
    !> 'm/s^2', 'cm/s2', 'cm/s^2', 'gal'; case and surrounding blanks ignored). An unknown
    !> name: SEISPULSE_INVALID_INPUT, the message "'<name>': unknown acceleration unit
    !> (allowed: ...)" (the caller puts the key in front).
    subroutine accel_unit_code(name, code, stat, errmsg)
        character(len=*), intent(in) :: name              !! the unit as written
        integer, intent(out) :: code                      !! UNITS_*, 0 when unknown
        integer, intent(out) :: stat                      !! SEISPULSE_SUCCESS or an error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer :: k, i
        stat = SEISPULSE_SUCCESS
        code = 0
        k = code_of(upper(adjustl(name)), [(upper(ACCEL_UNIT_NAMES(i)), i = 1, &
                                            size(ACCEL_UNIT_NAMES))])
        if (k == 0) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, quote(trim(adjustl(name))) &
                           //': unknown acceleration unit (allowed: '//unit_list()//')')
            return
        end if
        code = ACCEL_UNIT_CODES(k)
    end subroutine accel_unit_code

    !> The factor from an acceleration unit to g: a value in `name` times `factor` is in
    !> g (1 for g, 1/g for m/s2, 1/(100 g) for cm/s2 and gal). Names as accel_unit_code.
    subroutine accel_unit_factor(name, g, factor, stat, errmsg)
        character(len=*), intent(in) :: name              !! the unit as written
        real(dp), intent(in) :: g                         !! gravity (m/s^2), finite > 0
        real(dp), intent(out) :: factor                   !! to g; 0 on error
        integer, intent(out) :: stat                      !! SEISPULSE_SUCCESS or an error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer :: code
        factor = 0.0_dp
        call accel_unit_code(name, code, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        if (.not. finite_positive(g)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'g = '//num_str(g) &
                           //': must be a finite number > 0 (m/s^2)')
            return
        end if
        select case (code)
        case (UNITS_G)
            factor = 1.0_dp
        case (UNITS_M_S2)
            factor = 1.0_dp / g
        case default
            factor = 1.0_dp / (100.0_dp * g)
        end select
    end subroutine accel_unit_factor

    !> "g, m/s2, ..." (ACCEL_UNIT_NAMES).
    pure function unit_list() result(s)
        character(len=len_trim(unit_list_text())) :: s
        s = unit_list_text()
    end function unit_list

    !> unit_list() padded with blanks.
    pure function unit_list_text() result(s)
        character(len=size(ACCEL_UNIT_NAMES) * (len(ACCEL_UNIT_NAMES) + 2)) :: s
        integer :: i
        s = ACCEL_UNIT_NAMES(1)
        do i = 2, size(ACCEL_UNIT_NAMES)
            s = trim(s)//', '//trim(ACCEL_UNIT_NAMES(i))
        end do
    end function unit_list_text

    !> Values in `units` to g (in place); a non-finite result is an error.
    subroutine to_g(a, units, path, stat, errmsg)
        real(dp), intent(inout) :: a(:)
        integer, intent(in) :: units
        character(len=*), intent(in) :: path
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        integer :: i
        stat = SEISPULSE_SUCCESS
        select case (units)
        case (UNITS_M_S2)
            a(:) = a(:) / STANDARD_GRAVITY
        case (UNITS_CM_S2)
            a(:) = a(:) / (100.0_dp * STANDARD_GRAVITY)
        end select
        do i = 1, size(a)
            if (.not. ieee_is_finite(a(i))) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, path//': value number ' &
                               //int_str(i)//' is not finite after conversion to g')
                return
            end if
        end do
    end subroutine to_g

end module seispulse_records
