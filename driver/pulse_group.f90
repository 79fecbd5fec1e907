!> The &pulse group, shared by every analysis that drives something with one pulse
!> ('pulse', 'sliding', 'rocking', 'sdof_shock'): its keys, defaults, reading,
!> validation and the pulse_t it builds; and the time grid of a history under the pulse
!> (&history of 'sliding', &rocking of 'rocking'); the pulse family of an overturning
!> map (&map of 'rocking' and 'cylinder': unused keys, the header line). One code path,
!> so that a pulse means the same in every analysis.
module driver_pulse_group
    use, intrinsic :: iso_fortran_env, only: error_unit
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_value, ieee_quiet_nan
    use seispulse, only: dp, shortest_str, pulse_t, pulse_validate, pulse_kind_from_name, &
                         pulse_kind_name, &
                         SEISPULSE_SUCCESS, PULSE_EXPONENTIAL, PULSE_TRIANGULAR, PULSE_RICKER, &
                         PULSE_MP, PULSE_SINE_CYCLE, PULSE_COSINE_CYCLE, finite_positive, &
                         pulse_end_time, real_str, accel_unit_code, UNITS_G, UNITS_M_S2, &
                         UNITS_CM_S2
    use driver_namelist_scan, only: nml_group, lower
    use driver_input, only: find_group, check_keys, read_group, located, given
    implicit none
    private

    public :: pulse_input_t, pulse_keys, read_pulse_group, build_pulse, write_pulse_group
    public :: pulse_end, check_time_grid, time_grid, not_one
    public :: warn_unused_template, template_text

    !> Every key of &pulse.
    character(len=12), parameter :: pulse_keys(14) = [character(len=12) :: 'kind', 'amp', &
        'amp_unit', 'g', 'duration', 'beta', 'full', 'peak_frac', 'freq', 't0', 'gamma', &
        'nu_deg', 'vamp', 'cycles']

    !> What an analysis gets from &pulse.
    type :: pulse_input_t
        type(nml_group) :: group               !! the scanned group (an empty one if absent)
        type(pulse_t) :: p                     !! the validated pulse, SI
        integer :: code = PULSE_EXPONENTIAL    !! its kind, PULSE_*
        real(dp) :: g = 9.80665_dp             !! gravity (m/s2)
        real(dp) :: amp_g = 0.0_dp             !! amplitude in g, as given when amp_unit = 'g'
                                               !! (NaN for M&P: a velocity amplitude)
    end type pulse_input_t

    !> Most points of the time grid of a history.
    integer, parameter :: max_grid = 10000000

    ! namelist variables (defaults are set in set_defaults)
    character(len=32) :: kind, amp_unit
    real(dp) :: amp, g, duration, beta, peak_frac, freq, t0, gamma, nu_deg, vamp
    !> sine_cycle, cosine_cycle: number of cycles, a whole number in [1, 1e6]; read as a
    !> real so that 2.5 or NaN reach the library's check (which names `cycles`)
    real(dp) :: cycles
    logical :: full
    namelist /pulse/ kind, amp, amp_unit, g, duration, beta, full, peak_frac, freq, t0, &
        gamma, nu_deg, vamp, cycles

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
        cycles = 1.0_dp
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

    !> Set the defaults, then check the keys of &pulse and read it (if present).
    subroutine read_pulse_group(path, groups, pin, stat, errmsg)
        character(len=*), intent(in) :: path              !! input file (for messages)
        type(nml_group), intent(in) :: groups(:)          !! scanned groups
        type(pulse_input_t), intent(out) :: pin           !! receives the group
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        integer :: ip
        call set_defaults()
        errmsg = ''
        stat = 0
        ip = find_group(groups, 'pulse')
        if (ip > 0) then
            pin%group = groups(ip)
            call check_keys(path, pin%group, pulse_keys, stat, errmsg)
            if (stat /= 0) return
            call read_group(path, pin%group, read_pulse, stat, errmsg)
        else
            pin%group%name = 'pulse'
            pin%group%line = 0
            allocate(pin%group%items(0))
        end if
    end subroutine read_pulse_group

    !> Validate the values read and build the pulse (amplitude in m/s2). Warns on
    !> stderr about keys the kind does not use; `g_used`: the analysis always uses g.
    subroutine build_pulse(path, pin, stat, errmsg, g_used)
        character(len=*), intent(in) :: path              !! input file (for messages)
        type(pulse_input_t), intent(inout) :: pin         !! group in, pulse out
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        logical, intent(in), optional :: g_used
        character(len=256) :: msg
        integer :: code, i, unit_code
        real(dp) :: amp_si
        logical :: g_always

        g_always = .false.
        if (present(g_used)) g_always = g_used
        errmsg = ''
        stat = 1
        call pulse_kind_from_name(kind, code, i, msg)
        if (i /= SEISPULSE_SUCCESS) then
            errmsg = located(path, pin%group)//trim(msg)
            return
        end if
        pin%amp_g = ieee_value(pin%amp_g, ieee_quiet_nan)
        if (g_always .and. .not. finite_positive(g)) then
            errmsg = located(path, pin%group)//'g: must be a finite number > 0 (m/s2)'
            return
        end if
        amp_si = amp
        call accel_unit_code(amp_unit, unit_code, i, msg)
        if (i /= SEISPULSE_SUCCESS) then
            errmsg = located(path, pin%group)//'amp_unit = '//trim(msg)
            return
        end if
        select case (unit_code)
        case (UNITS_M_S2)
            if (code /= PULSE_MP) pin%amp_g = amp / g
        case (UNITS_CM_S2)
            if (code /= PULSE_MP) pin%amp_g = amp / (100.0_dp * g)
            amp_si = amp / 100.0_dp
        case (UNITS_G)
            if (.not. finite_positive(g)) then
                errmsg = located(path, pin%group)//'g: must be a finite number > 0 (m/s2)'
                return
            end if
            if (code /= PULSE_MP) pin%amp_g = amp
            ! SI for the library; the namelist variable keeps the value as given, so the
            ! echo reads back the same pulse
            amp_si = amp * g
        end select
        if (code == PULSE_MP) amp_si = vamp
        if (ieee_is_nan(t0)) then
            if (code == PULSE_MP) then
                t0 = 0.5_dp * gamma / freq
            else
                t0 = 1.5_dp / freq
            end if
        end if
        pin%p = pulse_t(kind=code, amp=amp_si, duration=duration, beta=beta, full=full, &
                        peak_frac=peak_frac, freq=freq, t0=t0, gamma=gamma, nu_deg=nu_deg, &
                        cycles=cycles)
        call pulse_validate(pin%p, i, msg)
        if (i /= SEISPULSE_SUCCESS) then
            errmsg = located(path, pin%group)//trim(msg)
            return
        end if
        pin%code = code
        pin%g = g
        call warn_unused(path, pin%group, code, g_always)
        stat = 0
    end subroutine build_pulse

    !> The end of the pulse for the default length of a history: pulse_end_time, or
    !> 2 t0 for the Ricker wavelet (which never ends).
    function pulse_end(pin) result(t)
        type(pulse_input_t), intent(in) :: pin
        real(dp) :: t
        if (pin%code == PULSE_RICKER) then
            t = 2.0_dp * pin%p%t0
        else
            t = pulse_end_time(pin%p)
        end if
    end function pulse_end

    !> Check the keys of a history's time grid given in `group` (t_end, or dt or npts):
    !> errmsg (after `where`) about the first bad one, '' if none.
    subroutine check_time_grid(where, group, t_end, dt, npts, errmsg)
        character(len=*), intent(in) :: where             !! "file:line: &group: "
        type(nml_group), intent(in) :: group
        real(dp), intent(in) :: t_end, dt                 !! s
        integer, intent(in) :: npts
        character(len=:), allocatable, intent(out) :: errmsg
        errmsg = ''
        if (given(group, 't_end') .and. .not. finite_positive(t_end)) then
            errmsg = where//'t_end = '//real_str(t_end)//': must be a finite number > 0 (s)'
        else if (given(group, 'npts') .and. given(group, 'dt')) then
            errmsg = where//'dt, npts: give one of them, not both'
        else if (given(group, 'dt') .and. .not. finite_positive(dt)) then
            errmsg = where//'dt = '//real_str(dt)//': must be a finite number > 0 (s)'
        else if (given(group, 'npts') .and. (npts < 2 .or. npts > max_grid)) then
            errmsg = where//'npts: must be in 2 .. 10000000'
        end if
    end subroutine check_time_grid

    !> The time grid of a history, 0 to t_last: every dt when dt > 0 (the last point at
    !> or just below t_last), else npts points (1001 when 0). errmsg (without the
    !> location) when dt gives too many points.
    subroutine time_grid(t_last, dt, npts, t, errmsg)
        real(dp), intent(in) :: t_last, dt                !! s
        integer, intent(in) :: npts
        real(dp), allocatable, intent(out) :: t(:)        !! s
        character(len=:), allocatable, intent(out) :: errmsg
        real(dp) :: step
        integer :: n, j
        errmsg = ''
        if (dt > 0.0_dp) then
            if (t_last / dt + 1.0_dp > max_grid) then
                errmsg = 'dt: too small, more than 1e7 points'
                return
            end if
            n = int(t_last / dt * (1.0_dp + 1.0e-12_dp)) + 1
            step = dt
        else
            n = npts
            if (n == 0) n = 1001
            step = t_last / (n - 1)
        end if
        allocate(t(n))
        t = step * [(real(j, dp), j = 0, n - 1)]
    end subroutine time_grid

    !> Echo the group as read and completed (for the log). `cycles` is echoed only when it
    !> is not 1 (the default), so that the echo of an input without it stays as it was.
    subroutine write_pulse_group(unit)
        integer, intent(in) :: unit
        if (not_one(cycles)) then
            write(unit, nml=pulse)
        else
            call echo_without_cycles(unit)
        end if
    end subroutine write_pulse_group

    !> x /= 1, NaN included (tested without an ordered comparison with NaN).
    elemental logical function not_one(x)
        real(dp), intent(in) :: x
        if (ieee_is_nan(x)) then
            not_one = .true.
        else
            not_one = abs(x - 1.0_dp) > 0.0_dp
        end if
    end function not_one

    !> The echo of &pulse without `cycles`: a local namelist of the same name hides the
    !> module's one here.
    subroutine echo_without_cycles(unit)
        integer, intent(in) :: unit
        namelist /pulse/ kind, amp, amp_unit, g, duration, beta, full, peak_frac, freq, t0, &
            gamma, nu_deg, vamp
        write(unit, nml=pulse)
    end subroutine echo_without_cycles

    !> Warn (stderr) about keys the chosen kind does not use: a likely slip.
    subroutine warn_unused(path, group, code, g_always)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: group
        integer, intent(in) :: code
        logical, intent(in) :: g_always
        integer :: i
        logical :: used
        do i = 1, size(group%items)
            select case (group%items(i)%key)
            case ('kind')
                used = .true.
            case ('g')
                used = code /= PULSE_MP .or. g_always
            case ('amp', 'amp_unit')
                used = code /= PULSE_MP
            case ('duration')
                used = code /= PULSE_MP .and. code /= PULSE_RICKER
            case ('beta', 'full')
                used = code == PULSE_EXPONENTIAL
            case ('peak_frac')
                used = code == PULSE_TRIANGULAR
            case ('freq', 't0')
                used = code == PULSE_MP .or. code == PULSE_RICKER
            case ('cycles')
                used = code == PULSE_SINE_CYCLE .or. code == PULSE_COSINE_CYCLE
            case default   ! gamma, nu_deg, vamp
                used = code == PULSE_MP
            end select
            if (.not. used) write(error_unit, '(a)') 'warning: '//located(path, group) &
                //group%items(i)%key//': not used by kind '//pulse_kind_name(code)
        end do
    end subroutine warn_unused

    ! ------------------------------------------------------------------------------
    ! The pulse family of an overturning map (&map of 'rocking' and 'cylinder')
    ! ------------------------------------------------------------------------------

    !> Warn (stderr) about template keys of a &map group the pulse family does not use.
    subroutine warn_unused_template(path, gm, code)
        character(len=*), intent(in) :: path              !! input file (for messages)
        type(nml_group), intent(in) :: gm                 !! the &map group
        integer, intent(in) :: code                       !! PULSE_* code of the family
        integer :: i
        logical :: used
        do i = 1, size(gm%items)
            select case (gm%items(i)%key)
            case ('beta', 'full')
                used = code == PULSE_EXPONENTIAL
            case ('peak_frac')
                used = code == PULSE_TRIANGULAR
            case ('t0_periods')
                used = code == PULSE_RICKER
            case ('cycles')
                used = code == PULSE_SINE_CYCLE .or. code == PULSE_COSINE_CYCLE
            case default
                used = .true.
            end select
            if (.not. used) write(error_unit, '(a)') 'warning: '//located(path, gm) &
                //gm%items(i)%key//': not used by kind '//pulse_kind_name(code)
        end do
    end subroutine warn_unused_template

    !> The shape parameters of a map's pulse family (the template at f_p = 1, so that its
    !> t0 is t0 f_p), for the header.
    function template_text(tpl) result(text)
        type(pulse_t), intent(in) :: tpl
        character(len=:), allocatable :: text
        select case (tpl%kind)
        case (PULSE_EXPONENTIAL)
            text = 'pulse shape: beta = '//shortest_str(tpl%beta)//', full = ' &
                   //trim(merge('.true. ', '.false.', tpl%full))
        case (PULSE_TRIANGULAR)
            text = 'pulse shape: peak_frac = '//shortest_str(tpl%peak_frac)
        case (PULSE_RICKER)
            text = 'pulse shape: t0 f_p = '//shortest_str(tpl%t0)
        case (PULSE_SINE_CYCLE, PULSE_COSINE_CYCLE)
            text = 'pulse shape: '//pulse_kind_name(tpl%kind)
            if (not_one(tpl%cycles)) text = text//', cycles = '//shortest_str(tpl%cycles)
        case default
            text = 'pulse shape: '//pulse_kind_name(tpl%kind)
        end select
    end function template_text

end module driver_pulse_group
