!> Analysis 'pulse': the time history t, a, v, d of any pulse of seispulse_pulses.
!>
!> Groups: &pulse (which pulse) and &time (where to sample it). Writes the table
!> <output>_pulse.txt / .csv with columns t (s), a (m/s2), a (g), v (m/s), d (m).
module driver_pulse
    use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite, ieee_value, &
                                             ieee_quiet_nan
    use seispulse, only: dp, pulse_t, pulse_validate, pulse_eval, pulse_end_time, &
                         pulse_kind_from_name, pulse_kind_name, SEISPULSE_SUCCESS, &
                         PULSE_EXPONENTIAL, PULSE_TRIANGULAR, PULSE_RICKER, PULSE_MP
    use seispulse_errors, only: real_str
    use driver_namelist_scan, only: nml_group, lower
    use driver_input, only: find_group, check_keys, read_group, located
    use driver_tables, only: write_tables
    implicit none
    private

    public :: run_pulse, pulse_groups

    !> Groups this analysis reads (besides &run).
    character(len=8), parameter :: pulse_groups(2) = [character(len=8) :: 'pulse', 'time']

    character(len=12), parameter :: pulse_keys(13) = [character(len=12) :: 'kind', 'amp', &
        'amp_unit', 'g', 'duration', 'beta', 'full', 'peak_frac', 'freq', 't0', 'gamma', &
        'nu_deg', 'vamp']
    character(len=8), parameter :: time_keys(4) = [character(len=8) :: 't_start', 't_end', &
        'dt', 'npts']

    ! namelist variables (the driver's only state; defaults are set in set_defaults)
    character(len=32) :: kind, amp_unit
    real(dp) :: amp, g, duration, beta, peak_frac, freq, t0, gamma, nu_deg, vamp
    logical :: full
    real(dp) :: t_start, t_end, dt
    integer :: npts
    namelist /pulse/ kind, amp, amp_unit, g, duration, beta, full, peak_frac, freq, t0, &
        gamma, nu_deg, vamp
    namelist /time/ t_start, t_end, dt, npts

    integer, parameter :: max_points = 10000000

contains

    subroutine set_defaults()
        real(dp) :: nan
        nan = ieee_value(nan, ieee_quiet_nan)
        kind = 'exponential'
        amp = 1.0_dp
        amp_unit = 'm/s2'
        g = 9.80665_dp
        duration = 1.0_dp
        beta = 0.0_dp
        full = .false.
        peak_frac = 0.5_dp
        freq = 1.0_dp
        t0 = nan          ! NaN: Ricker 1.5/freq, M&P gamma/(2 freq)
        gamma = 2.0_dp
        nu_deg = 0.0_dp
        vamp = 1.0_dp
        t_start = 0.0_dp
        t_end = nan       ! NaN: 1.25 x the end of the pulse (Ricker: 2 t0)
        dt = 0.0_dp
        npts = 0          ! neither dt nor npts: 1001 points
    end subroutine set_defaults

    subroutine read_pulse(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        if (len(text) > 0) then
            read(text, nml=pulse, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=pulse, iostat=ios, iomsg=iomsg)
        end if
    end subroutine read_pulse

    subroutine read_time(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        if (len(text) > 0) then
            read(text, nml=time, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=time, iostat=ios, iomsg=iomsg)
        end if
    end subroutine read_time

    !> Read &pulse and &time, evaluate, write the tables; print where they went.
    subroutine run_pulse(path, groups, prefix, stat, errmsg)
        character(len=*), intent(in) :: path              !! input file (for messages)
        type(nml_group), intent(in) :: groups(:)          !! scanned groups
        character(len=*), intent(in) :: prefix            !! output prefix
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        type(pulse_t) :: p
        type(nml_group) :: gp, gt
        character(len=256) :: msg
        character(len=512) :: files(2)
        character(len=120) :: comments(3)
        real(dp), allocatable :: t(:), table(:, :)
        integer :: ip, it, code, i

        call set_defaults()
        ip = find_group(groups, 'pulse')
        it = find_group(groups, 'time')
        gp%name = 'pulse'
        gp%line = 0
        allocate(gp%items(0))
        gt = gp
        gt%name = 'time'
        if (ip > 0) gp = groups(ip)
        if (it > 0) gt = groups(it)
        if (ip > 0) then
            call check_keys(path, gp, pulse_keys, stat, errmsg)
            if (stat /= 0) return
            call read_group(path, gp, read_pulse, stat, errmsg)
            if (stat /= 0) return
        end if
        if (it > 0) then
            call check_keys(path, gt, time_keys, stat, errmsg)
            if (stat /= 0) return
            call read_group(path, gt, read_time, stat, errmsg)
            if (stat /= 0) return
        end if

        ! --- the pulse
        stat = 1
        call pulse_kind_from_name(kind, code, i, msg)
        if (i /= SEISPULSE_SUCCESS) then
            errmsg = located(path, gp)//trim(msg)
            return
        end if
        select case (lower(trim(amp_unit)))
        case ('m/s2')
        case ('g')
            if (.not. (ieee_is_finite(g) .and. g > 0.0_dp)) then
                errmsg = located(path, gp)//'g: must be a finite number > 0 (m/s2)'
                return
            end if
            amp = amp * g
        case default
            errmsg = located(path, gp)//'amp_unit = '''//trim(amp_unit) &
                     //''': unknown unit (allowed: m/s2, g)'
            return
        end select
        if (code == PULSE_MP) amp = vamp
        if (ieee_is_nan(t0)) then
            if (code == PULSE_MP) then
                t0 = 0.5_dp * gamma / freq
            else
                t0 = 1.5_dp / freq
            end if
        end if
        p = pulse_t(kind=code, amp=amp, duration=duration, beta=beta, full=full, &
                    peak_frac=peak_frac, freq=freq, t0=t0, gamma=gamma, nu_deg=nu_deg)
        call pulse_validate(p, i, msg)
        if (i /= SEISPULSE_SUCCESS) then
            errmsg = located(path, gp)//trim(msg)
            return
        end if
        call warn_unused(path, gp, code)

        ! --- the time grid
        if (ieee_is_nan(t_end)) then
            if (code == PULSE_RICKER) then
                t_end = 2.0_dp * p%t0
            else
                t_end = 1.25_dp * pulse_end_time(p)
            end if
        end if
        if (.not. ieee_is_finite(t_start)) then
            errmsg = located(path, gt)//'t_start: must be a finite number (s)'
            return
        end if
        if (.not. (ieee_is_finite(t_end) .and. t_end > t_start)) then
            errmsg = located(path, gt)//'t_end: must be a finite number > t_start (s)'
            return
        end if
        if (npts /= 0 .and. dt > 0.0_dp) then
            errmsg = located(path, gt)//'dt, npts: give one of them, not both'
            return
        end if
        if (.not. (dt >= 0.0_dp)) then
            errmsg = located(path, gt)//'dt: must be a number > 0 (s)'
            return
        end if
        if (dt > 0.0_dp) then
            if ((t_end - t_start) / dt + 1.0_dp > max_points) then
                errmsg = located(path, gt)//'dt: too small, more than 1e7 points'
                return
            end if
            npts = int((t_end - t_start) / dt * (1.0_dp + 1.0e-12_dp)) + 1
        else if (npts == 0) then
            npts = 1001
        end if
        if (npts < 2 .or. npts > max_points) then
            errmsg = located(path, gt)//'npts: must be in 2 .. 10000000'
            return
        end if
        if (.not. (dt > 0.0_dp)) dt = (t_end - t_start) / (npts - 1)

        ! --- echo the effective input
        write(output_unit, nml=pulse)
        write(output_unit, nml=time)

        ! --- evaluate and write
        allocate(t(npts), table(npts, 5))
        t = t_start + dt * [(real(i, dp), i = 0, npts - 1)]
        call pulse_eval(p, t, table(:, 2), table(:, 4), table(:, 5), i, msg)
        if (i /= SEISPULSE_SUCCESS) then
            errmsg = located(path, gp)//trim(msg)
            return
        end if
        table(:, 1) = t
        table(:, 3) = table(:, 2) / g
        comments(1) = 'seispulse analysis pulse: '//pulse_kind_name(code)
        comments(2) = 'input: '//trim(path)
        comments(3) = 'a (g) uses g = '//real_str(g)//' m/s2'
        call write_tables(prefix, 'pulse', comments, &
            [character(len=8) :: 't', 'a', 'a', 'v', 'd'], &
            [character(len=8) :: 's', 'm/s2', 'g', 'm/s', 'm'], table, files, stat, errmsg)
        if (stat /= 0) then
            errmsg = path//': &run: output: '//errmsg
            return
        end if
        write(output_unit, '(a)') 'pulse table written to '//trim(files(1))//' and ' &
            //trim(files(2))
    end subroutine run_pulse

    !> Warn (stderr) about keys the chosen kind does not use: a likely slip.
    subroutine warn_unused(path, group, code)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: group
        integer, intent(in) :: code
        integer :: i
        logical :: used
        do i = 1, size(group%items)
            select case (group%items(i)%key)
            case ('kind')
                used = .true.
            case ('amp', 'amp_unit', 'g')
                used = code /= PULSE_MP
            case ('duration')
                used = code /= PULSE_MP .and. code /= PULSE_RICKER
            case ('beta', 'full')
                used = code == PULSE_EXPONENTIAL
            case ('peak_frac')
                used = code == PULSE_TRIANGULAR
            case ('freq', 't0')
                used = code == PULSE_MP .or. code == PULSE_RICKER
            case default   ! gamma, nu_deg, vamp
                used = code == PULSE_MP
            end select
            if (.not. used) write(error_unit, '(a)') 'warning: '//located(path, group) &
                //group%items(i)%key//': not used by kind '//pulse_kind_name(code)
        end do
    end subroutine warn_unused

end module driver_pulse
