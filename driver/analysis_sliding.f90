!> Analysis 'sliding': a rigid block on a frictional plane (Newmark sliding block) hit
!> by one pulse: onsets, stops, slips and sliding velocities of the forward (downhill)
!> and reverse (uphill) slides, one row per friction value.
!>
!> Groups: &pulse (driver_pulse_group), &block (friction, slope, sweeps), &method
!> (closed forms or the event-driven integrator) and &history (optional time
!> histories). Tables <output>_sliding and, with &history, <output>_sliding_history.
!> The numbers come from seispulse_sliding_closed (closed forms, exponential pulse) and
!> seispulse_sliding_sim (any pulse); the driver only reads, checks, converts units
!> and writes.
module driver_sliding
    use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_value, ieee_quiet_nan
    use seispulse, only: dp, shortest_str, pulse_eval, pulse_kind_name, SEISPULSE_SUCCESS, &
                         PULSE_EXPONENTIAL, &
                         PULSE_MP, real_str, sliding_block_t, full_cycle_t, block_response, &
                         block_response_eta, inclined_resistances, summarize_slides, &
                         sliding_mode_name, friction_t, stickslip_result_t, stickslip_pulse, &
                         finite_at_least, positive
    use driver_namelist_scan, only: nml_group, lower
    use driver_input, only: find_group, located, join, read_optional, given, list_length, &
                            list_item
    use driver_input, only: missing_group
    use driver_input, only: output_located
    use driver_pulse_group, only: pulse_input_t, pulse_keys, read_pulse_group, build_pulse, &
                                  write_pulse_group, pulse_end, check_time_grid, time_grid
    use driver_tables, only: write_tables, delete_files, say_written, category_kind
    use driver_echo, only: echo_unit
    implicit none
    private

    public :: run_sliding, sliding_groups, sliding_tables

    !> Groups this analysis reads (besides &run).
    character(len=8), parameter :: sliding_groups(4) = [character(len=8) :: 'pulse', &
        'block', 'method', 'history']

    !> Tables this analysis may write (removed with the echo file after an input error).
    character(len=15), parameter :: sliding_tables(2) = [character(len=15) :: 'sliding', &
        'sliding_history']

    character(len=14), parameter :: block_keys(10) = [character(len=14) :: 'mu', &
        'slope_deg', 'xi_deg', 'static_factor', 'static_reverse', 'along_plane', 'eta1', &
        'eta2', 'mu_list', 'eta_list']
    character(len=8), parameter :: method_keys(1) = [character(len=8) :: 'solver']
    character(len=8), parameter :: history_keys(3) = [character(len=8) :: 't_end', 'npts', &
        'dt']
    character(len=10), parameter :: solver_names(3) = [character(len=10) :: 'auto', &
        'closed', 'integrator']

    !> Most values in a sweep (mu_list, eta_list).
    integer, parameter :: max_cases = 1000
    !> Most rows of the history table.
    integer, parameter :: max_rows = 10000000

    integer, parameter :: INPUT_MU = 1, INPUT_ETA = 2

    !> A sweep (mu_list or eta_list) was given: messages name the row.
    logical :: sweep = .false.

    ! namelist variables (defaults are set in set_defaults)
    real(dp) :: mu, slope_deg, xi_deg, static_factor, eta1, eta2
    real(dp) :: mu_list(max_cases), eta_list(max_cases)
    logical :: static_reverse, along_plane
    character(len=32) :: solver
    real(dp) :: t_end, dt
    integer :: npts
    namelist /block/ mu, slope_deg, xi_deg, static_factor, static_reverse, along_plane, &
        eta1, eta2, mu_list, eta_list
    namelist /method/ solver
    namelist /history/ t_end, npts, dt

    !> A time grid of one case.
    type :: real_array
        real(dp), allocatable :: x(:)
    end type real_array

    !> One row of the table, SI.
    type :: case_t
        real(dp) :: mu = 0.0_dp        !! friction coefficient (NaN: eta given)
        real(dp) :: eta1 = 0.0_dp      !! forward (downhill) resistance / A_g
        real(dp) :: eta2 = 0.0_dp      !! reverse (uphill) resistance / A_g
        type(sliding_block_t) :: r             !! the response (eta1, eta2 of r unused)
    end type case_t

contains

    subroutine set_defaults()
        real(dp) :: nan
        nan = ieee_value(nan, ieee_quiet_nan)
        mu = nan
        slope_deg = 0.0_dp
        xi_deg = 0.0_dp
        static_factor = 1.0_dp
        static_reverse = .false.
        along_plane = .true.
        eta1 = nan
        eta2 = nan
        mu_list = nan
        eta_list = nan
        solver = 'auto'
        t_end = nan       ! NaN: 1.25 x the time the block comes to rest, >= the pulse end
        dt = 0.0_dp
        npts = 0          ! neither dt nor npts: 1001 points
    end subroutine set_defaults

    subroutine read_block(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        if (len(text) > 0) then
            read(text, nml=block, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=block, iostat=ios, iomsg=iomsg)
        end if
    end subroutine read_block

    subroutine read_method(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        if (len(text) > 0) then
            read(text, nml=method, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=method, iostat=ios, iomsg=iomsg)
        end if
    end subroutine read_method

    subroutine read_history(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        if (len(text) > 0) then
            read(text, nml=history, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=history, iostat=ios, iomsg=iomsg)
        end if
    end subroutine read_history

    !> Read the groups, compute every case, write the tables; print where they went.
    subroutine run_sliding(path, groups, prefix, stat, errmsg)
        character(len=*), intent(in) :: path              !! input file (for messages)
        type(nml_group), intent(in) :: groups(:)          !! scanned groups
        character(len=*), intent(in) :: prefix            !! output prefix
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        type(pulse_input_t) :: pin
        type(nml_group) :: gb, gm, gh
        type(case_t), allocatable :: cases(:)
        real(dp), allocatable :: hist(:, :)
        character(len=512) :: files(2), hfiles(2)
        logical :: closed, with_history
        integer :: input_mode, i

        call set_defaults()
        call read_pulse_group(path, groups, pin, stat, errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'block', block_keys, read_block, gb, stat, errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'method', method_keys, read_method, gm, stat, errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'history', history_keys, read_history, gh, stat, &
                           errmsg)
        if (stat /= 0) return
        with_history = find_group(groups, 'history') > 0

        call build_pulse(path, pin, stat, errmsg, g_used=.true.)
        if (stat /= 0) return
        stat = 1
        if (find_group(groups, 'block') == 0) then
            errmsg = missing_group(path, 'block')//' (it gives the friction: mu, eta1, ' &
                     //'mu_list or eta_list)'
            return
        end if
        call check_block(path, gb, pin, cases, input_mode, errmsg)
        if (len(errmsg) > 0) return
        call choose_solver(path, gm, pin, closed, errmsg)
        if (len(errmsg) > 0) return
        if (with_history) then
            call check_history(path, gh, errmsg)
            if (len(errmsg) > 0) return
        end if

        ! --- echo the effective input
        call write_pulse_group(echo_unit())
        write(echo_unit(), nml=block)
        write(echo_unit(), nml=method)
        if (with_history) write(echo_unit(), nml=history)

        ! --- compute every case (nothing is written before all of them succeed)
        do i = 1, size(cases)
            if (closed) then
                call solve_closed(pin, input_mode, cases(i), errmsg)
            else
                call solve_integrator(pin, input_mode, cases(i), errmsg)
            end if
            if (len(errmsg) > 0) then
                if (names_pulse_key(errmsg)) then
                    errmsg = located(path, pin%group)//errmsg
                else
                    errmsg = located(path, gb)//case_label(input_mode, i, size(cases))//errmsg
                end if
                return
            end if
        end do
        if (with_history) then
            call history_table(pin, input_mode, cases, hist, errmsg)
            if (len(errmsg) > 0) then
                errmsg = located(path, gh)//errmsg
                return
            end if
        end if

        ! --- write
        call write_result(path, prefix, pin, closed, input_mode, cases, files, stat, errmsg)
        if (stat /= 0) then
            errmsg = output_located(path)//errmsg
            return
        end if
        if (with_history) then
            call write_tables(prefix, 'sliding_history', &
                [character(len=512) :: 'seispulse analysis sliding: time histories of the ' &
                 //'event-driven integrator, one block per case', 'input: '//trim(path), &
                 'u, u'': slip and sliding velocity of the block relative to the plane ' &
                 //'(positive forward/downhill)'], &
                [character(len=8) :: 'case', 't', 'a_g', 'u', 'u'''], &
                [character(len=8) :: '-', 's', 'm/s2', 'm', 'm/s'], hist, hfiles, stat, errmsg, &
                kinds=[character(len=4) :: 'int', '', '', '', ''])
            if (stat /= 0) then
                call delete_files(files)
                errmsg = output_located(path)//errmsg
                return
            end if
        end if
        call say_written('sliding table', files)
        if (with_history) call say_written('sliding history', hfiles)
        stat = 0
    end subroutine run_sliding

    !> A library message about a parameter of &pulse ("gamma = ...: ...").
    pure logical function names_pulse_key(msg)
        character(len=*), intent(in) :: msg
        integer :: k
        k = scan(msg, ' =:')
        names_pulse_key = .false.
        if (k > 1) names_pulse_key = any(pulse_keys == msg(1:k - 1))
    end function names_pulse_key

    !> Check &block and make the list of cases. errmsg is empty on success.
    subroutine check_block(path, gb, pin, cases, input_mode, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gb
        type(pulse_input_t), intent(in) :: pin
        type(case_t), allocatable, intent(out) :: cases(:)
        integer, intent(out) :: input_mode
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: where, which
        character(len=8), parameter :: choices(4) = [character(len=8) :: 'mu', 'eta1', &
            'mu_list', 'eta_list']
        real(dp) :: nan
        integer :: i, n, ngiven

        nan = ieee_value(nan, ieee_quiet_nan)
        where = located(path, gb)
        errmsg = ''
        input_mode = INPUT_MU
        ngiven = 0
        which = ''
        do i = 1, size(choices)
            if (given(gb, trim(choices(i)))) then
                ngiven = ngiven + 1
                if (ngiven > 1) which = which//', '
                which = which//trim(choices(i))
            end if
        end do
        if (given(gb, 'eta2') .and. .not. given(gb, 'eta1')) then
            errmsg = where//'eta2: only with eta1 (eta_list is symmetric: eta2 = eta1)'
            return
        end if
        if (ngiven == 0) then
            errmsg = where//'mu: missing (give one of mu, eta1, mu_list, eta_list)'
            return
        else if (ngiven > 1) then
            errmsg = where//which//': give only one of mu, eta1, mu_list, eta_list'
            return
        end if
        if (given(gb, 'eta1') .or. given(gb, 'eta_list')) then
            input_mode = INPUT_ETA
            do i = 1, 2
                which = trim(merge('slope_deg', 'xi_deg   ', i == 1))
                if (given(gb, which)) then
                    errmsg = where//which//': not with eta1 or eta_list (the resistances ' &
                             //'a_y/A_g already include the slope; give mu to use slope_deg ' &
                             //'and xi_deg)'
                    return
                end if
            end do
            if (given(gb, 'along_plane')) write(error_unit, '(a)') 'warning: '//where &
                //'along_plane: not used with eta1 or eta_list (no slope: K = 1)'
            if (pin%code == PULSE_MP) then
                errmsg = where//'eta1: a_y/A_g needs an acceleration amplitude A_g, and ' &
                         //'kind mavroeidis_papageorgiou has a velocity amplitude (give mu)'
                return
            end if
            if (.not. abs(pin%p%amp) > 0.0_dp) then
                errmsg = located(path, pin%group)//'amp = 0.0: eta1 and eta_list are ' &
                         //'fractions of the amplitude, which must not be zero'
                return
            end if
        end if
        if (.not. finite_at_least(static_factor, 1.0_dp)) then
            errmsg = where//'static_factor = '//real_str(static_factor)//': must be a finite ' &
                     //'number >= 1 (static over kinetic friction)'
            return
        end if

        ! --- the cases
        sweep = given(gb, 'mu_list') .or. given(gb, 'eta_list')
        if (given(gb, 'mu_list')) then
            call list_length(mu_list, 'mu_list', n, errmsg)
            if (len(errmsg) > 0) then
                errmsg = where//errmsg
                return
            end if
            allocate(cases(n))
            cases%mu = mu_list(1:n)
        else if (given(gb, 'eta_list')) then
            call list_length(eta_list, 'eta_list', n, errmsg)
            if (len(errmsg) > 0) then
                errmsg = where//errmsg
                return
            end if
            allocate(cases(n))
            cases%mu = nan
            cases%eta1 = eta_list(1:n)
            cases%eta2 = eta_list(1:n)
        else if (given(gb, 'eta1')) then
            allocate(cases(1))
            cases%mu = nan
            cases%eta1 = eta1
            cases%eta2 = eta1
            if (given(gb, 'eta2')) cases%eta2 = eta2
        else
            allocate(cases(1))
            cases%mu = mu
        end if

        ! --- the values: mu, slope and xi through the library's own checks
        do i = 1, size(cases)
            if (input_mode == INPUT_MU) then
                call resistances(cases(i)%mu, 1.0_dp, cases(i)%eta1, cases(i)%eta2, &
                                 errmsg)
                if (len(errmsg) > 0) errmsg = case_label(input_mode, i, size(cases))//errmsg
            else if (sweep) then
                call check_eta(cases(i)%eta1, list_item('eta_list', i), errmsg)
            else
                call check_eta(cases(i)%eta1, 'eta1', errmsg)
                if (len(errmsg) == 0) call check_eta(cases(i)%eta2, 'eta2', errmsg)
            end if
            if (len(errmsg) > 0) then
                errmsg = where//errmsg
                return
            end if
        end do
    end subroutine check_block

    !> "mu_list(3): " for a row of a sweep, "" for a single case.
    function case_label(input_mode, i, n) result(label)
        integer, intent(in) :: input_mode, i, n
        character(len=:), allocatable :: label
        label = ''
        if (.not. sweep .or. n < 1) return
        if (input_mode == INPUT_MU) then
            label = list_item('mu_list', i)//': '
        else
            label = list_item('eta_list', i)//': '
        end if
    end function case_label

    subroutine check_eta(eta, name, errmsg)
        real(dp), intent(in) :: eta
        character(len=*), intent(in) :: name
        character(len=:), allocatable, intent(out) :: errmsg
        errmsg = ''
        if (positive(eta)) return     ! +inf allowed: no sliding that way
        errmsg = name//' = ' &
            //real_str(eta)//': must be > 0 (a_y/A_g; eta >= 1 means no sliding that way)'
    end subroutine check_eta

    !> eta1, eta2 of the library (Eq. 1.31) for friction mu and amplitude ag_over_g.
    subroutine resistances(mu_value, ag_over_g, e1, e2, errmsg, k1, k2)
        real(dp), intent(in) :: mu_value, ag_over_g
        real(dp), intent(out) :: e1, e2
        character(len=:), allocatable, intent(out) :: errmsg
        real(dp), intent(out), optional :: k1, k2
        character(len=512) :: msg
        real(dp) :: f1, f2
        integer :: stat
        msg = ''
        errmsg = ''
        call inclined_resistances(mu_value, ag_over_g, slope_deg, xi_deg, e1, e2, f1, f2, &
                                  stat, msg)
        if (stat /= SEISPULSE_SUCCESS) errmsg = trim(msg)
        if (present(k1)) k1 = f1
        if (present(k2)) k2 = f2
    end subroutine resistances

    !> Closed forms or the integrator (&method solver).
    subroutine choose_solver(path, gm, pin, closed, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gm
        type(pulse_input_t), intent(in) :: pin
        logical, intent(out) :: closed
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: name
        errmsg = ''
        closed = .false.
        name = trim(lower(adjustl(solver)))
        select case (name)
        case ('auto')
            closed = pin%code == PULSE_EXPONENTIAL .and. pin%p%amp > 0.0_dp
        case ('closed')
            if (pin%code /= PULSE_EXPONENTIAL) then
                errmsg = located(path, gm)//'solver = '''//trim(solver)//''': closed forms ' &
                         //'exist for kind exponential only (this pulse: ' &
                         //pulse_kind_name(pin%code)//'; use ''auto'' or ''integrator'')'
            else if (.not. pin%p%amp > 0.0_dp) then
                errmsg = located(path, gm)//'solver = '''//trim(solver)//''': the closed ' &
                         //'forms need amp > 0 (amp = '//real_str(pin%p%amp)//' m/s2; use ' &
                         //'''auto'' or ''integrator'')'
            end if
            closed = .true.
        case ('integrator')
        case default
            errmsg = located(path, gm)//'solver = '''//trim(solver)//''': unknown solver ' &
                     //'(allowed: '//join(solver_names)//')'
        end select
    end subroutine choose_solver

    !> Check &history (the grid itself depends on each case).
    subroutine check_history(path, gh, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gh
        character(len=:), allocatable, intent(out) :: errmsg
        call check_time_grid(located(path, gh), gh, t_end, dt, npts, errmsg)
    end subroutine check_history

    ! ------------------------------------------------------------------------------
    ! Solvers
    ! ------------------------------------------------------------------------------

    !> Closed forms of seispulse_sliding_closed (exponential pulse, amp > 0).
    subroutine solve_closed(pin, input_mode, c, errmsg)
        type(pulse_input_t), intent(in) :: pin
        integer, intent(in) :: input_mode
        type(case_t), intent(inout) :: c
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=512) :: msg
        real(dp) :: td
        integer :: stat
        msg = ''
        errmsg = ''
        td = pin%p%duration
        if (input_mode == INPUT_MU) then
            call block_response(c%mu, pin%amp_g, td, pin%p%beta, pin%p%full, slope_deg, &
                                xi_deg, static_factor, static_reverse, along_plane, pin%g, &
                                c%r, stat, msg)
            if (stat /= SEISPULSE_SUCCESS) then
                errmsg = trim(msg)
                return
            end if
            c%eta1 = c%r%eta1
            c%eta2 = c%r%eta2
            return
        end if
        ! eta given: the dimensionless solution, in SI (no slope: K = 1)
        call block_response_eta(c%eta1, c%eta2, 1.0_dp, 1.0_dp, pin%p%amp / pin%g, td, &
                                pin%p%beta, pin%p%full, static_factor, static_reverse, pin%g, &
                                c%r, stat, msg)
        if (stat /= SEISPULSE_SUCCESS) errmsg = trim(msg)
    end subroutine solve_closed

    !> Friction of the integrator and the along-plane factors for one case.
    subroutine integrator_friction(pin, input_mode, c, fr, k1, k2, errmsg)
        type(pulse_input_t), intent(in) :: pin
        integer, intent(in) :: input_mode
        type(case_t), intent(inout) :: c
        type(friction_t), intent(out) :: fr
        real(dp), intent(out) :: k1, k2
        character(len=:), allocatable, intent(out) :: errmsg
        real(dp) :: ag_ref, e1, e2
        logical :: has_amp
        errmsg = ''
        k1 = 1.0_dp
        k2 = 1.0_dp
        ! A_g of the eta columns: |amp| (none for M&P, a velocity pulse, or amp = 0)
        has_amp = pin%code /= PULSE_MP .and. abs(pin%p%amp) > 0.0_dp
        if (input_mode == INPUT_MU) then
            ! a_y = eta A_g does not depend on A_g (Eq. 1.31); with no amplitude, A_g = g
            ag_ref = 1.0_dp
            if (has_amp) ag_ref = abs(pin%amp_g)
            call resistances(c%mu, ag_ref, e1, e2, errmsg, k1, k2)
            if (len(errmsg) > 0) return
            if (.not. along_plane) then
                k1 = 1.0_dp
                k2 = 1.0_dp
            end if
            fr%ay_fwd = e1 * (ag_ref * pin%g)
            fr%ay_rev = e2 * (ag_ref * pin%g)
            if (has_amp) then
                c%eta1 = e1
                c%eta2 = e2
            else
                c%eta1 = ieee_value(e1, ieee_quiet_nan)
                c%eta2 = c%eta1
            end if
        else
            fr%ay_fwd = c%eta1 * abs(pin%p%amp)
            fr%ay_rev = c%eta2 * abs(pin%p%amp)
        end if
        fr%static_factor = static_factor
        fr%static_all = static_reverse
    end subroutine integrator_friction

    !> The event-driven integrator of seispulse_sliding_sim (any pulse).
    subroutine solve_integrator(pin, input_mode, c, errmsg)
        type(pulse_input_t), intent(in) :: pin
        integer, intent(in) :: input_mode
        type(case_t), intent(inout) :: c
        character(len=:), allocatable, intent(out) :: errmsg
        type(friction_t) :: fr
        type(stickslip_result_t) :: res
        character(len=512) :: msg
        type(full_cycle_t) :: f
        real(dp) :: k1, k2
        logical :: reverse_possible
        integer :: stat, i
        call integrator_friction(pin, input_mode, c, fr, k1, k2, errmsg)
        if (len(errmsg) > 0) return
        msg = ''
        call stickslip_pulse(pin%p, fr, res, stat, msg)
        if (stat /= SEISPULSE_SUCCESS) then
            errmsg = trim(msg)
            return
        end if
        ! the first slide each way; a lone forward slide of an exponential full cycle is
        ! 'stuck' when the second lobe could start a reverse slide (as in full_cycle)
        reverse_possible = .false.
        if (pin%code == PULSE_EXPONENTIAL .and. pin%p%full) &
            reverse_possible = fr%ay_rev * merge(fr%static_factor, 1.0_dp, fr%static_all) &
                               < abs(pin%p%amp)
        call summarize_slides(res, reverse_possible, f)
        c%r = sliding_block_t(mode=f%mode, eta1=c%eta1, eta2=c%eta2, t_y1=f%tau_y1, t_m1=f%tau_m1, &
                      u_m1=k1 * f%um1, t_y2=f%tau_y2, t_m2=f%tau_m2, u_m2=k2 * f%um2, &
                      u_res=res%u_final, v_m1=k1 * f%vm1, v_m2=k2 * f%vm2)
        ! u_res along the plane: u_final plus (K - 1) x each slide
        do i = 1, size(res%slides)
            associate (s => res%slides(i))
                c%r%u_res = c%r%u_res + (merge(k1, k2, s%direction > 0) - 1.0_dp) &
                            * (s%u_stop - s%u_start)
            end associate
        end do
    end subroutine solve_integrator

    ! ------------------------------------------------------------------------------
    ! History
    ! ------------------------------------------------------------------------------

    !> The history table: case, t, a_g, u, u' for every case, from the integrator.
    subroutine history_table(pin, input_mode, cases, hist, errmsg)
        type(pulse_input_t), intent(in) :: pin
        integer, intent(in) :: input_mode
        type(case_t), intent(in) :: cases(:)
        real(dp), allocatable, intent(out) :: hist(:, :)
        character(len=:), allocatable, intent(out) :: errmsg
        type(case_t) :: c
        type(friction_t) :: fr
        type(stickslip_result_t) :: res
        character(len=512) :: msg
        real(dp), allocatable :: t(:), a(:), v(:), d(:), u(:), w(:)
        real(dp) :: k1, k2, t_stop, t_last, du
        integer :: i, j, k, n, row, stat, nrows
        integer, allocatable :: counts(:)
        type(real_array), allocatable :: grids(:)

        errmsg = ''
        allocate(counts(size(cases)), grids(size(cases)))
        ! --- the grid of each case
        do i = 1, size(cases)
            c = cases(i)
            call integrator_friction(pin, input_mode, c, fr, k1, k2, errmsg)
            if (len(errmsg) > 0) return
            t_last = t_end
            if (ieee_is_nan(t_end)) then
                msg = ''
                call stickslip_pulse(pin%p, fr, res, stat, msg)
                if (stat /= SEISPULSE_SUCCESS) then
                    errmsg = 't_end: '//trim(msg)
                    return
                end if
                t_stop = 0.0_dp
                do j = 1, size(res%slides)
                    t_stop = max(t_stop, res%slides(j)%t_stop)
                end do
                t_last = max(1.25_dp * t_stop, pulse_end(pin))
            end if
            call time_grid(t_last, dt, npts, grids(i)%x, errmsg)
            if (len(errmsg) > 0) return
            counts(i) = size(grids(i)%x)
        end do
        if (sum(real(counts, dp)) > max_rows) then
            errmsg = 'npts: too many rows (cases x points > 10000000)'
            return
        end if
        nrows = sum(counts)
        allocate(hist(nrows, 5))
        row = 0
        do i = 1, size(cases)
            c = cases(i)
            n = counts(i)
            call integrator_friction(pin, input_mode, c, fr, k1, k2, errmsg)
            if (len(errmsg) > 0) return
            allocate(t(n), a(n), v(n), d(n), u(n), w(n))
            t = grids(i)%x
            msg = ''
            call stickslip_pulse(pin%p, fr, res, stat, msg, t_grid=t, u_grid=u, w_grid=w)
            if (stat == SEISPULSE_SUCCESS) call pulse_eval(pin%p, t, a, v, d, stat, msg)
            if (stat /= SEISPULSE_SUCCESS) then
                errmsg = trim(msg)
                return
            end if
            hist(row + 1:row + n, 1) = real(i, dp)
            hist(row + 1:row + n, 2) = t
            hist(row + 1:row + n, 3) = a
            ! along the plane: each slide's increment times its K (K = 1: u, w as they are)
            hist(row + 1:row + n, 4) = u
            hist(row + 1:row + n, 5) = w
            do k = 1, size(res%slides)
                associate (s => res%slides(k))
                    do j = 1, n
                        if (t(j) <= s%t_start) cycle
                        if (t(j) >= s%t_stop) then
                            du = s%u_stop - s%u_start
                        else
                            du = u(j) - s%u_start
                            hist(row + j, 5) = merge(k1, k2, s%direction > 0) * w(j)
                        end if
                        hist(row + j, 4) = hist(row + j, 4) &
                                           + (merge(k1, k2, s%direction > 0) - 1.0_dp) * du
                    end do
                end associate
            end do
            row = row + n
            deallocate(t, a, v, d, u, w)
        end do
    end subroutine history_table

    ! ------------------------------------------------------------------------------
    ! Output
    ! ------------------------------------------------------------------------------

    subroutine write_result(path, prefix, pin, closed, input_mode, cases, files, stat, errmsg)
        character(len=*), intent(in) :: path, prefix
        type(pulse_input_t), intent(in) :: pin
        logical, intent(in) :: closed
        integer, intent(in) :: input_mode
        type(case_t), intent(in) :: cases(:)
        character(len=*), intent(out) :: files(2)
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        real(dp), allocatable :: table(:, :)
        character(len=512) :: comments(6)
        character(len=:), allocatable :: slips
        character(len=32) :: names(0:5)
        integer :: i, m

        allocate(table(size(cases), 14))
        do i = 1, size(cases)
            associate (c => cases(i), r => cases(i)%r)
                table(i, :) = [real(i, dp), c%mu, c%eta1, c%eta2, real(r%mode, dp), r%t_y1, &
                               r%t_m1, r%u_m1, r%t_y2, r%t_m2, r%u_m2, r%u_res, r%v_m1, r%v_m2]
            end associate
        end do
        do m = 0, 5
            names(m) = sliding_mode_name(m)
        end do
        if (input_mode == INPUT_MU .and. along_plane) then
            slips = 'slips and velocities along the plane (times the factors K of ' &
                    //'doc/sliding.md section 7)'
        else
            slips = 'slips and velocities of the normalized problem (K = 1)'
        end if
        if (closed) then
            comments(1) = 'seispulse analysis sliding: '//pulse_kind_name(pin%code) &
                          //' pulse, closed forms (seispulse_sliding_closed)'
        else
            comments(1) = 'seispulse analysis sliding: '//pulse_kind_name(pin%code) &
                          //' pulse, event-driven integrator (seispulse_sliding_sim)'
        end if
        comments(2) = 'input: '//trim(path)
        comments(3) = '1 = first forward (downhill) slide, 2 = first reverse (uphill) ' &
                      //'slide; times from the start of the pulse; NaN: no such slide'
        comments(4) = 'eta1, eta2 = a_y/A_g forward, reverse (NaN: no acceleration ' &
                      //'amplitude); mu = NaN: eta given directly'
        comments(5) = slips//'; u_res: residual slip, forward positive'
        comments(6) = 'g = '//shortest_str(pin%g)//' m/s2, slope_deg = '//shortest_str(slope_deg) &
                      //', xi_deg = '//shortest_str(xi_deg)//', static_factor = ' &
                      //shortest_str(static_factor)
        call write_tables(prefix, 'sliding', comments, &
            [character(len=8) :: 'case', 'mu', 'eta1', 'eta2', 'mode', 't_y1', 't_m1', 'u_m1', &
             't_y2', 't_m2', 'u_m2', 'u_res', 'v_m1', 'v_m2'], &
            [character(len=4) :: '-', '-', '-', '-', '-', 's', 's', 'm', 's', 's', 'm', 'm', &
             'm/s', 'm/s'], table, files, stat, errmsg, &
            kinds=[character(len=256) :: 'int', '', '', '', category_kind(names)], summary=.true.)
    end subroutine write_result

end module driver_sliding
