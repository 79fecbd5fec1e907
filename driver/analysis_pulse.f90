!> Analysis 'pulse': the time history t, a, v, d of any pulse of seispulse_pulses.
!>
!> Groups: &pulse (which pulse) and &time (where to sample it). Writes the table
!> <output>_pulse.txt / .csv with columns t (s), a (m/s2), a_in_g (g), v (m/s), d (m).
module driver_pulse
    use, intrinsic :: iso_fortran_env, only: output_unit
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_is_finite, ieee_value, &
                                             ieee_quiet_nan
    use seispulse, only: dp, shortest_str, pulse_eval, pulse_end_time, pulse_kind_name, &
                         SEISPULSE_SUCCESS, &
                         PULSE_RICKER, real_str
    use driver_namelist_scan, only: nml_group
    use driver_input, only: find_group, check_keys, read_group, located
    use driver_input, only: output_located
    use driver_pulse_group, only: pulse_input_t, read_pulse_group, build_pulse, &
                                  write_pulse_group
    use driver_tables, only: write_tables, say_written
    use driver_echo, only: echo_unit
    implicit none
    private

    public :: run_pulse, pulse_groups, pulse_tables

    !> Groups this analysis reads (besides &run).
    character(len=8), parameter :: pulse_groups(2) = [character(len=8) :: 'pulse', 'time']

    !> Tables this analysis may write (removed with the echo file after an input error).
    character(len=5), parameter :: pulse_tables(1) = [character(len=5) :: 'pulse']

    character(len=8), parameter :: time_keys(4) = [character(len=8) :: 't_start', 't_end', &
        'dt', 'npts']

    ! namelist variables of &time (&pulse: driver_pulse_group; defaults in set_defaults)
    real(dp) :: t_start, t_end, dt
    integer :: npts
    namelist /time/ t_start, t_end, dt, npts

    integer, parameter :: max_points = 10000000

contains

    subroutine set_defaults()
        real(dp) :: nan
        nan = ieee_value(nan, ieee_quiet_nan)
        t_start = 0.0_dp
        t_end = nan       ! NaN: 1.25 x the end of the pulse (Ricker: 2 t0)
        dt = 0.0_dp
        npts = 0          ! neither dt nor npts: 1001 points
    end subroutine set_defaults

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
        type(pulse_input_t) :: pin
        type(nml_group) :: gt
        character(len=256) :: msg
        character(len=512) :: files(2)
        character(len=120) :: comments(3)
        real(dp), allocatable :: t(:), table(:, :)
        integer :: it, i

        call set_defaults()
        call read_pulse_group(path, groups, pin, stat, errmsg)
        if (stat /= 0) return
        it = find_group(groups, 'time')
        gt%name = 'time'
        gt%line = 0
        allocate(gt%items(0))
        if (it > 0) then
            gt = groups(it)
            call check_keys(path, gt, time_keys, stat, errmsg)
            if (stat /= 0) return
            call read_group(path, gt, read_time, stat, errmsg)
            if (stat /= 0) return
        end if

        ! --- the pulse
        call build_pulse(path, pin, stat, errmsg)
        if (stat /= 0) return
        stat = 1

        ! --- the time grid
        if (ieee_is_nan(t_end)) then
            if (pin%code == PULSE_RICKER) then
                t_end = 2.0_dp * pin%p%t0
            else
                t_end = 1.25_dp * pulse_end_time(pin%p)
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
        call write_pulse_group(echo_unit())
        write(echo_unit(), nml=time)

        ! --- evaluate and write
        allocate(t(npts), table(npts, 5))
        t = t_start + dt * [(real(i, dp), i = 0, npts - 1)]
        call pulse_eval(pin%p, t, table(:, 2), table(:, 4), table(:, 5), i, msg)
        if (i /= SEISPULSE_SUCCESS) then
            errmsg = located(path, pin%group)//trim(msg)
            return
        end if
        table(:, 1) = t
        table(:, 3) = table(:, 2) / pin%g
        comments(1) = 'seispulse analysis pulse: '//pulse_kind_name(pin%code)
        comments(2) = 'input: '//trim(path)
        comments(3) = 'a_in_g = a/g, g = '//shortest_str(pin%g)//' m/s2'
        call write_tables(prefix, 'pulse', comments, &
            [character(len=8) :: 't', 'a', 'a_in_g', 'v', 'd'], &
            [character(len=8) :: 's', 'm/s2', 'g', 'm/s', 'm'], table, files, stat, errmsg)
        if (stat /= 0) then
            errmsg = output_located(path)//errmsg
            return
        end if
        call say_written('pulse table', files)
    end subroutine run_pulse

end module driver_pulse
