!> Analysis 'sdof_shock' of the linear oscillator (doc/oscillator.md): the shock spectrum
!> of one closed-form pulse.
!>
!> Groups &pulse (driver_pulse_group, as in 'pulse' and 'sliding') and &sdof_shock (t_d/T
!> ratios or periods, damping ratios); table <output>_sdof_shock, the spectra of the
!> closed-form response from rest (free vibration after the pulse included) from
!> seispulse_sdof_closed's sdof_pulse_spectrum, also divided by the pulse's peak ground
!> acceleration.
module driver_sdof_shock
    use, intrinsic :: iso_fortran_env, only: output_unit
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_positive_inf
    use seispulse, only: dp, shortest_str, SEISPULSE_SUCCESS, pseudo_spectra, sdof_pulse_spectrum, &
                         pulse_peak_accel, pulse_kind_name, PULSE_RICKER, PULSE_MP
    use driver_namelist_scan, only: nml_group
    use driver_input, only: find_group, located, read_optional, given, value_name
    use driver_input, only: missing_group
    use driver_input, only: output_located
    use driver_tables, only: write_tables, say_written
    use driver_pulse_group, only: pulse_input_t, read_pulse_group, build_pulse, &
                                  write_pulse_group
    use driver_sdof_common, only: max_periods, max_dampings, check_dampings
    use driver_axis, only: axis_values
    use driver_echo, only: echo_unit
    implicit none
    private

    public :: run_sdof_shock, sdof_shock_groups, sdof_shock_tables

    !> Groups this analysis reads (besides &run).
    character(len=12), parameter :: sdof_shock_groups(2) = [character(len=12) :: 'pulse', &
        'sdof_shock']

    !> Tables this analysis may write (removed with the echo file after an input error).
    character(len=10), parameter :: sdof_shock_tables(1) = [character(len=10) :: 'sdof_shock']

    character(len=12), parameter :: shock_keys(8) = [character(len=12) :: 'ratios', &
        'ratio_range', 'ratio_count', 'periods', 'period_range', 'period_count', 'spacing', &
        'damping']

    ! namelist variables (defaults are set in set_defaults; &pulse: driver_pulse_group)
    real(dp) :: ratios(max_periods), ratio_range(2), periods(max_periods), period_range(2), &
                damping(max_dampings)
    integer :: ratio_count, period_count
    character(len=32) :: spacing
    namelist /sdof_shock/ ratios, ratio_range, ratio_count, periods, period_range, &
        period_count, spacing, damping

contains

    subroutine set_defaults()
        real(dp) :: nan
        nan = ieee_value(nan, ieee_quiet_nan)
        ratios = nan
        ratio_range = nan
        ratio_count = 0
        periods = nan
        period_range = nan
        period_count = 0
        spacing = 'linear'
        damping = nan
    end subroutine set_defaults

    subroutine read_shock(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        if (len(text) > 0) then
            read(text, nml=sdof_shock, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=sdof_shock, iostat=ios, iomsg=iomsg)
        end if
    end subroutine read_shock

    !> Read and check &pulse and &sdof_shock, compute the shock spectrum of the pulse,
    !> write the table; print where it went. stat > 0 with errmsg on an input or output
    !> error.
    subroutine run_sdof_shock(path, groups, prefix, stat, errmsg)
        character(len=*), intent(in) :: path              !! input file (for messages)
        type(nml_group), intent(in) :: groups(:)          !! scanned groups
        character(len=*), intent(in) :: prefix            !! output prefix
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        type(pulse_input_t) :: pin
        type(nml_group) :: gk
        character(len=:), allocatable :: where, grid, td_text
        real(dp), allocatable :: axis(:), td_t(:), t_osc(:), dampings(:), table(:, :), &
                                 sd(:, :), sv(:, :), sa(:, :), psv(:, :), psa(:, :)
        character(len=512) :: files(2)
        character(len=1024) :: comments(7), msg
        real(dp) :: td, apk, tpk, pga, inf, nan
        integer :: np, nd, i, j, row, st
        logical :: by_ratio, by_period

        call set_defaults()
        call read_pulse_group(path, groups, pin, stat, errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'sdof_shock', shock_keys, read_shock, gk, stat, &
                           errmsg)
        if (stat /= 0) return
        stat = 1
        if (find_group(groups, 'sdof_shock') == 0) then
            errmsg = missing_group(path, 'sdof_shock')//' (it gives the oscillators: ratios ' &
                     //'t_d/T or periods, as a list or a range, and the damping ratios)'
            return
        end if
        call build_pulse(path, pin, stat, errmsg, g_used=.true.)
        if (stat /= 0) return
        stat = 1
        where = located(path, gk)

        ! --- the oscillators: t_d/T ratios or periods
        by_ratio = given(gk, 'ratios') .or. given(gk, 'ratio_range')
        by_period = given(gk, 'periods') .or. given(gk, 'period_range')
        if (by_ratio .and. by_period) then
            errmsg = where//trim(merge('ratios     ', 'ratio_range', given(gk, 'ratios'))) &
                     //', '//trim(merge('periods     ', 'period_range', given(gk, 'periods'))) &
                     //': give only one of them (t_d/T ratios, or periods in s)'
            return
        end if
        if (by_period) then
            if (given(gk, 'ratio_count')) then
                errmsg = where//'ratio_count: only with ratio_range'
                return
            end if
            call axis_values(gk, 'periods', 'period', periods, period_range, period_count, &
                             spacing, .false., .false., max_periods, axis, grid, errmsg)
        else
            if (given(gk, 'period_count')) then
                errmsg = where//'period_count: only with period_range'
                return
            end if
            call axis_values(gk, 'ratios', 'ratio', ratios, ratio_range, ratio_count, spacing, &
                             .true., .false., max_periods, axis, grid, errmsg)
            if (len(errmsg) == 0 .and. size(axis) == 0) errmsg = 'ratios: missing (give ' &
                //'ratios = a list of t_d/T, or ratio_range = min, max with ratio_count; ' &
                //'or periods in s)'
        end if
        if (len(errmsg) > 0) then
            errmsg = where//errmsg
            return
        end if
        call check_dampings(gk, damping, dampings, errmsg)
        if (len(errmsg) > 0) then
            errmsg = where//errmsg
            return
        end if

        ! --- t_d, T and t_d/T
        if (pin%code == PULSE_RICKER .or. pin%code == PULSE_MP) then
            td = 1.0_dp / pin%p%freq
            td_text = 't_d = 1/freq = '//shortest_str(td)//' s (the pulse period)'
        else
            td = pin%p%duration
            td_text = 't_d = duration = '//shortest_str(td)//' s'
        end if
        np = size(axis)
        inf = ieee_value(inf, ieee_positive_inf)
        nan = ieee_value(nan, ieee_quiet_nan)
        allocate(td_t(np), t_osc(np))
        if (by_period) then
            t_osc = axis
            do i = 1, np
                td_t(i) = inf
                if (t_osc(i) > 0.0_dp) td_t(i) = td / t_osc(i)
            end do
        else
            td_t = axis
            t_osc = td / td_t
        end if

        ! --- echo the effective input
        call write_pulse_group(echo_unit())
        call echo_shock(by_period, axis, dampings)

        ! --- compute
        msg = ''
        call pulse_peak_accel(pin%p, apk, tpk, st, msg)
        if (st /= SEISPULSE_SUCCESS) then
            errmsg = located(path, pin%group)//trim(msg)
            return
        end if
        pga = apk / pin%g
        nd = size(dampings)
        allocate(table(np * nd, 10), sd(np, 1), sv(np, 1), sa(np, 1), psv(np, 1), psa(np, 1))
        do j = 1, nd
            do i = 1, np
                ! one period at a time, so that a refusal names its value
                msg = ''
                call sdof_pulse_spectrum(pin%p, t_osc(i:i), dampings(j), sd(i:i, 1), &
                                         sv(i:i, 1), sa(i:i, 1), st, msg)
                if (st /= SEISPULSE_SUCCESS) then
                    if (by_period) then
                        errmsg = where//value_name('periods', i, np)//' = ' &
                            //shortest_str(t_osc(i)) &
                                 //': '//trim(msg)
                    else
                        errmsg = where//value_name('ratios', i, np)//' = '//shortest_str(td_t(i)) &
                                 //' (T = t_d/ratio = '//shortest_str(t_osc(i))//' s, '//td_text &
                                 //'): '//trim(msg)
                    end if
                    return
                end if
            end do
            sa = sa / pin%g
            call pseudo_spectra(t_osc, sd, pin%g, pga, psv, psa)
            do i = 1, np
                row = (j - 1) * np + i
                table(row, 1:8) = [dampings(j), td_t(i), t_osc(i), sd(i, 1), sv(i, 1), &
                                   sa(i, 1), psv(i, 1), psa(i, 1)]
                table(row, 9:10) = nan
                if (pga > 0.0_dp) table(row, 9:10) = [sa(i, 1), psa(i, 1)] / pga
            end do
        end do

        ! --- write
        comments(1) = 'seispulse analysis sdof_shock: shock spectrum of the linear ' &
                      //'oscillator under one pulse (closed form, from rest), one row per ' &
                      //'damping ratio and period'
        comments(2) = 'input: '//trim(path)
        comments(3) = 'pulse: '//pulse_kind_name(pin%code)//', '//td_text//', peak ground ' &
                      //'acceleration PGA = '//shortest_str(apk)//' m/s2 = '//shortest_str(pga) &
                          //' g at t = ' &
                      //shortest_str(tpk)//' s; g = '//shortest_str(pin%g)//' m/s2'
        comments(4) = 'oscillators: '//grid
        comments(5) = 'SD, SV: largest |z|, |z''| (relative to the ground); SA: largest ' &
                      //'|a_g + z''''| (absolute acceleration); over all t >= 0, the free ' &
                      //'vibration after the pulse included; PSV = omega SD, PSA = omega^2 SD / g'
        comments(6) = 'SA/PGA, PSA/PGA: the dynamic coefficients (the shock spectrum ' &
                      //'against t_d/T); T = 0 (t_d/T = inf): the ground, SA = PSA = PGA'
        comments(7) = 'undamped rectangle: SA/PGA = 2 sin(pi t_d/T) for t_d/T <= 1/2, else 2 ' &
                      //'(the book''s 1 + 2 pi t_d/T is an upper bound)'
        call write_tables(prefix, 'sdof_shock', comments, &
            [character(len=8) :: 'damping', 't_d/T', 'T', 'SD', 'SV', 'SA', 'PSV', 'PSA', &
             'SA/PGA', 'PSA/PGA'], &
            [character(len=8) :: '-', '-', 's', 'm', 'm/s', 'g', 'm/s', 'g', '-', '-'], table, &
            files, stat, errmsg)
        if (stat /= 0) then
            errmsg = output_located(path)//errmsg
            return
        end if
        call say_written('sdof_shock table', files)

    end subroutine run_sdof_shock

    !> &sdof_shock with the values in use (the ratios or the periods as a list).
    subroutine echo_shock(by_period, values, dampings)
        logical, intent(in) :: by_period
        real(dp), intent(in) :: values(:), dampings(:)
        if (by_period) then
            call echo_shock_periods(values, dampings)
        else
            call echo_shock_ratios(values, dampings)
        end if
    end subroutine echo_shock

    subroutine echo_shock_periods(values, dampings)
        real(dp), intent(in) :: values(:), dampings(:)
        real(dp) :: periods(size(values)), damping(size(dampings))
        namelist /sdof_shock/ periods, damping
        periods = values
        damping = dampings
        write(echo_unit(), nml=sdof_shock)
    end subroutine echo_shock_periods

    subroutine echo_shock_ratios(values, dampings)
        real(dp), intent(in) :: values(:), dampings(:)
        real(dp) :: ratios(size(values)), damping(size(dampings))
        namelist /sdof_shock/ ratios, damping
        ratios = values
        damping = dampings
        write(echo_unit(), nml=sdof_shock)
    end subroutine echo_shock_ratios

end module driver_sdof_shock
