!> Checks and helpers shared by the analyses that run a rocking body ('rocking' and
!> 'cylinder'): the run options t_max and rtol, the restitution and the model, where a
!> library message belongs, the pulse family of an overturning map, and the progress
!> lines of a long map, and the run of a block under one record (with its history grid).
!> One code path, so that these keys mean and read the same in both.
module driver_rocking_common
    use, intrinsic :: iso_fortran_env, only: error_unit, int64
    use, intrinsic :: ieee_arithmetic, only: ieee_is_nan, ieee_value, ieee_quiet_nan
    use seispulse, only: dp, pi, pulse_t, pulse_validate, pulse_kind_from_name, &
                         SEISPULSE_SUCCESS, PULSE_RICKER, PULSE_MP, MAP_AXES_DIMENSIONLESS, &
                         real_str, positive, in_closed, finite_at_least, rocking_block_t, &
                         rocking_run_t, rock_record, ROCK_RUN_TIME_LIMIT
    use driver_namelist_scan, only: nml_group, lower
    use driver_input, only: located, join, given, name_index, list_item
    use driver_records, only: record_in_t, record_out_t, load_record, report
    use driver_tables, only: stack
    use driver_axis, only: axis_values
    use driver_pulse_group, only: time_grid
    use driver_tables, only: category_kind
    use driver_records, only: record_place
    implicit none
    private

    public :: check_run_options, restitution_and_model, locate_run_message
    public :: map_kind, map_template, progress_t
    public :: axes_names, map_axes_code, map_grids, map_axes_header, map_table
    public :: rock_on_record, rock_records, record_at
    public :: run_summary_kinds
    public :: map_class_names, run_outcome_names, winkler_outcome_names, map_class_line

    character(len=10), parameter :: model_names(2) = [character(len=10) :: 'nonlinear', &
        'linearized']
    !> The axis systems of a map, in the order of the MAP_AXES_* codes.
    !> One vocabulary for the overturning events of every driver table (maps and run
    !> summaries of rocking, cylinder and winkler): the library's rocking outcome names.
    !> The classes of an overturning map cell, by code (-1: undecided, the step budget
    !> ran out). `safe` (does not overturn) has no single run outcome: a run that does
    !> not overturn ends in rest or no_uplift (rocking, cylinder) or safe (winkler).
    character(len=21), parameter :: map_class_names(0:3) = [character(len=21) :: 'safe', &
        'overturn_no_impact', 'overturn_one_impact', 'overturn_many_impacts']
    !> The outcome of a rocking or cylinder run, by code (ROCK_* outcome codes).
    character(len=21), parameter :: run_outcome_names(0:5) = [character(len=21) :: 'rest', &
        'no_uplift', map_class_names(1:3), 'time_limit']
    !> The outcome of a winkler run, by code (WR_RUN_*: safe, the three overturns, then
    !> time_limit).
    character(len=21), parameter :: winkler_outcome_names(0:4) = [character(len=21) :: &
        map_class_names(0:3), 'time_limit']
    !> The header line of a map table naming its classes.
    character(len=*), parameter :: map_class_line = 'class: safe (does not overturn), ' &
        //'overturn_no_impact, overturn_one_impact, overturn_many_impacts (overturns after ' &
        //'no, one, more impacts: the run outcomes of the same names), undecided (the step ' &
        //'budget ran out)'
    character(len=13), parameter :: axes_names(2) = [character(len=13) :: 'dimensionless', &
        'dimensional']

    !> A map prints progress once it has run this long (s), then at most every
    !> `progress_every` seconds.
    real(dp), parameter :: progress_after = 2.0_dp, progress_every = 3.0_dp

    !> Progress lines of a map computed row by row ("map: row i/n" on stderr; with the
    !> elapsed time and an estimate of the time left when started with timing).
    type :: progress_t
        integer(int64) :: c_start = 0, c_last = 0, rate = 1
        logical :: printed = .false.
        logical :: timing = .false.
    contains
        procedure :: start => progress_start
        procedure :: row => progress_row
        procedure :: done => progress_done
    end type progress_t

contains

    !> t_max > 0 (s) or +Inf, rtol in [1e-14, 1e-3]: errmsg (after `where`) about the
    !> first bad one, '' if none.
    subroutine check_run_options(where, t_max, rtol, errmsg)
        character(len=*), intent(in) :: where             !! "file:line: &group: "
        real(dp), intent(in) :: t_max, rtol
        character(len=:), allocatable, intent(out) :: errmsg
        errmsg = ''
        if (.not. positive(t_max)) then
            errmsg = where//'t_max = '//real_str(t_max)//': must be a number > 0 (s) or ' &
                     //'+Inf (no limit)'
        else if (.not. in_closed(rtol, 1.0e-14_dp, 1.0e-3_dp)) then
            errmsg = where//'rtol = '//real_str(rtol)//': must be in [1e-14, 1e-3]'
        end if
    end subroutine check_run_options

    !> The keys e (given in `group`: in [0, 1]; else e_run is left as it is) and model
    !> ('nonlinear' or 'linearized', case and blanks ignored; model receives the clean
    !> name). errmsg (after `where`) on failure, else ''.
    subroutine restitution_and_model(where, group, e, model, e_run, linearized, errmsg)
        character(len=*), intent(in) :: where             !! "file:line: &group: "
        type(nml_group), intent(in) :: group
        real(dp), intent(in) :: e                         !! the value read
        character(len=*), intent(inout) :: model
        real(dp), intent(inout) :: e_run                  !! restitution of the runs
        logical, intent(out) :: linearized
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: name
        errmsg = ''
        linearized = .false.
        if (given(group, 'e')) then
            if (.not. in_closed(e, 0.0_dp, 1.0_dp)) then
                errmsg = where//'e = '//real_str(e)//': the coefficient of restitution ' &
                         //'must be in [0, 1]'
                return
            end if
            e_run = e
        end if
        name = trim(lower(adjustl(model)))
        select case (name)
        case ('nonlinear')
            linearized = .false.
        case ('linearized')
            linearized = .true.
        case default
            errmsg = where//'model = '''//trim(model)//''': unknown model (allowed: ' &
                     //join(model_names)//')'
            return
        end select
        model = name
    end subroutine restitution_and_model

    !> Where a library message about a run belongs, by the key it starts with: &pulse
    !> (pulse_keys), the run's group (run_keys), else the body's group.
    function locate_run_message(path, msg, pulse_group, pulse_keys, run_group, run_keys, &
                                body_group) result(full_msg)
        character(len=*), intent(in) :: path, msg
        type(nml_group), intent(in) :: pulse_group, run_group, body_group
        character(len=*), intent(in) :: pulse_keys(:), run_keys(:)
        character(len=:), allocatable :: full_msg
        character(len=:), allocatable :: key
        integer :: k
        k = scan(msg, ' =:(')
        key = ''
        if (k > 1) key = msg(1:k - 1)
        if (any(pulse_keys == key)) then
            full_msg = located(path, pulse_group)//msg
        else if (any(run_keys == key)) then
            full_msg = located(path, run_group)//msg
        else
            full_msg = located(path, body_group)//msg
        end if
    end function locate_run_message

    !> The pulse family of a map: its PULSE_* code (not M&P). errmsg (after `where`) on
    !> failure, else ''.
    subroutine map_kind(where, kind, code, errmsg)
        character(len=*), intent(in) :: where             !! "file:line: &map: "
        character(len=*), intent(in) :: kind
        integer, intent(out) :: code
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=512) :: msg
        integer :: st
        errmsg = ''
        msg = ''
        call pulse_kind_from_name(kind, code, st, msg)
        if (st /= SEISPULSE_SUCCESS) then
            errmsg = where//trim(msg)
        else if (code == PULSE_MP) then
            errmsg = where//'kind = '''//trim(kind)//''': maps take an acceleration pulse ' &
                     //'with a time scale (not mavroeidis_papageorgiou)'
        end if
    end subroutine map_kind

    !> The template of a map's pulse family at a unit time scale (f_p = 1, so t0 = t0 f_p),
    !> checked. errmsg (after `where`) on failure, else ''.
    subroutine map_template(where, code, beta, full, peak_frac, t0_periods, cycles, tpl, &
                            errmsg)
        character(len=*), intent(in) :: where             !! "file:line: &map: "
        integer, intent(in) :: code                       !! PULSE_* code
        real(dp), intent(in) :: beta, peak_frac, t0_periods, cycles
        logical, intent(in) :: full
        type(pulse_t), intent(out) :: tpl
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=512) :: msg
        integer :: st
        errmsg = ''
        msg = ''
        tpl = pulse_t(kind=code, amp=1.0_dp, duration=1.0_dp, beta=beta, full=full, &
                      peak_frac=peak_frac, freq=1.0_dp, t0=t0_periods, cycles=cycles)
        if (code == PULSE_RICKER .and. .not. finite_at_least(t0_periods, 0.0_dp)) then
            errmsg = where//'t0_periods = '//real_str(t0_periods)//': must be a finite ' &
                     //'number >= 0 (the centre of the wavelet times f_p)'
            return
        end if
        call pulse_validate(tpl, st, msg)
        if (st /= SEISPULSE_SUCCESS) errmsg = where//trim(msg)
    end subroutine map_template

    !> The axis system of a map (&map axes; case and blanks ignored): its MAP_AXES_* code
    !> (0 and errmsg after `where` when unknown, else errmsg '').
    subroutine map_axes_code(where, axes, axes_code, errmsg)
        character(len=*), intent(in) :: where             !! "file:line: &map: "
        character(len=*), intent(in) :: axes              !! the value read
        integer, intent(out) :: axes_code
        character(len=:), allocatable, intent(out) :: errmsg
        errmsg = ''
        axes_code = name_index(axes, axes_names)
        if (axes_code == 0) errmsg = where//'axes = '''//trim(axes)//''': unknown axes ' &
                                     //'(allowed: '//join(axes_names)//')'
    end subroutine map_axes_code

    !> The two grids of a map on the axis system `axes_code`: x (freq_ratio > 0, or freq_hz
    !> (Hz) > 0) and y (amp_ratio >= 0, or pga (g) >= 0), each a list or a range
    !> `<stem>_range` with `<stem>_count`; the keys of the other system are refused. grid_x,
    !> grid_y say how they were given (header), ykey names the y list (messages). errmsg
    !> (after `where`) on failure, else ''.
    subroutine map_grids(where, gm, axes_code, freq_ratio, freq_range, freq_count, &
                         amp_ratio, amp_range, amp_count, freq_hz, freq_hz_range, &
                         freq_hz_count, pga, pga_range, pga_count, max_list, xs, ys, grid_x, &
                         grid_y, ykey, errmsg)
        character(len=*), intent(in) :: where             !! "file:line: &map: "
        type(nml_group), intent(in) :: gm                 !! the &map group
        integer, intent(in) :: axes_code                  !! MAP_AXES_* code
        real(dp), intent(in) :: freq_ratio(:), freq_range(2), amp_ratio(:), amp_range(2)
        real(dp), intent(in) :: freq_hz(:), freq_hz_range(2), pga(:), pga_range(2)
        integer, intent(in) :: freq_count, amp_count, freq_hz_count, pga_count, max_list
        real(dp), allocatable, intent(out) :: xs(:), ys(:)
        character(len=:), allocatable, intent(out) :: grid_x, grid_y, ykey
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: grid
        errmsg = ''
        grid_x = ''
        grid_y = ''
        ykey = ''
        if (axes_code == MAP_AXES_DIMENSIONLESS) then
            call refuse('freq_hz', 'dimensional')
            call refuse('pga', 'dimensional')
            if (len(errmsg) > 0) return
            call axis_values(gm, 'freq_ratio', 'freq', freq_ratio, freq_range, freq_count, &
                             'linear', .true., .false., max_list, xs, grid, errmsg, &
                             required=.true., count_optional=.true., hint=.false., &
                             real_numbers=.true.)
            ykey = 'amp_ratio'
            grid_x = grid
            if (len(errmsg) == 0) call axis_values(gm, 'amp_ratio', 'amp', amp_ratio, &
                amp_range, amp_count, 'linear', .false., .false., max_list, ys, grid, errmsg, &
                required=.true., count_optional=.true., hint=.false., real_numbers=.true.)
        else
            call refuse('freq', 'dimensionless')
            call refuse('amp', 'dimensionless')
            if (len(errmsg) > 0) return
            call axis_values(gm, 'freq_hz', 'freq_hz', freq_hz, freq_hz_range, &
                             freq_hz_count, 'linear', .true., .false., max_list, xs, grid, &
                             errmsg, required=.true., count_optional=.true., hint=.false., &
                             real_numbers=.true.)
            ykey = 'pga'
            grid_x = grid
            if (len(errmsg) == 0) call axis_values(gm, 'pga', 'pga', pga, pga_range, &
                pga_count, 'linear', .false., .false., max_list, ys, grid, errmsg, &
                required=.true., count_optional=.true., hint=.false., real_numbers=.true.)
        end if
        if (len(errmsg) > 0) then
            errmsg = where//errmsg
            return
        end if
        grid_y = grid

    contains

        !> The keys of the other axis system are an error.
        subroutine refuse(stem, other)
            character(len=*), intent(in) :: stem, other
            character(len=:), allocatable :: list_key
            integer :: k
            if (len(errmsg) > 0) return
            list_key = stem
            if (stem == 'freq') list_key = 'freq_ratio'
            if (stem == 'amp') list_key = 'amp_ratio'
            do k = 1, 3
                select case (k)
                case (1)
                    if (given(gm, list_key)) errmsg = list_key
                case (2)
                    if (given(gm, stem//'_range')) errmsg = stem//'_range'
                case default
                    if (given(gm, stem//'_count')) errmsg = stem//'_count'
                end select
                if (len(errmsg) > 0) exit
            end do
            if (len(errmsg) > 0) errmsg = where//errmsg//': only with axes = '''//other &
                                          //''' (now axes = '''//trim(axes_names(axes_code)) &
                                          //''')'
        end subroutine refuse

    end subroutine map_grids

    !> The four axis columns of a map cell, the chosen system first: freq_ratio, amp_ratio,
    !> freq_hz (Hz), pga (g) on the dimensionless axes, else freq_hz, pga, freq_ratio,
    !> amp_ratio; freq_ratio = 2 pi freq_hz/p, amp_ratio = pga/tan(theta_c) with the rigid
    !> p (rad/s) and theta_c (rad) of the body.
    pure function map_axes_row(axes_code, x, y, p, theta_c) result(row)
        integer, intent(in) :: axes_code                  !! MAP_AXES_* code
        real(dp), intent(in) :: x, y                      !! the cell on the chosen axes
        real(dp), intent(in) :: p, theta_c
        real(dp) :: row(4)
        real(dp) :: fr, ar
        if (axes_code == MAP_AXES_DIMENSIONLESS) then
            fr = x
            ar = y
            row = [fr, ar, fr * p / (2.0_dp * pi), ar * tan(theta_c)]
        else
            fr = 2.0_dp * pi * x / p
            ar = y / tan(theta_c)
            row = [x, y, fr, ar]
        end if
    end function map_axes_row

    !> Names and units of the columns of map_table: the four axis columns of map_axes_row,
    !> 'class' (-), and with `compare` (the name of the comparison's class column) that
    !> column and 'diff' (-).
    subroutine map_axes_header(axes_code, names, units, compare)
        integer, intent(in) :: axes_code                  !! MAP_AXES_* code
        character(len=12), allocatable, intent(out) :: names(:)
        character(len=4), allocatable, intent(out) :: units(:)
        character(len=*), intent(in), optional :: compare
        if (axes_code == MAP_AXES_DIMENSIONLESS) then
            names = [character(len=12) :: 'freq_ratio', 'amp_ratio', 'freq_hz', 'pga', 'class']
            units = [character(len=4) :: '-', '-', 'Hz', 'g', '-']
        else
            names = [character(len=12) :: 'freq_hz', 'pga', 'freq_ratio', 'amp_ratio', 'class']
            units = [character(len=4) :: 'Hz', 'g', '-', '-', '-']
        end if
        if (present(compare)) then
            names = [character(len=12) :: names, compare, 'diff']
            units = [character(len=4) :: units, '-', '-']
        end if
    end subroutine map_axes_header

    !> The table of a map, amplitudes outer and frequencies inner: per cell the four axis
    !> columns (map_axes_row), the class, and with a comparison map (classes_b and diff,
    !> both or neither) its class and the difference code.
    subroutine map_table(axes_code, xs, ys, p, theta_c, classes, table, classes_b, diff)
        integer, intent(in) :: axes_code                  !! MAP_AXES_* code
        real(dp), intent(in) :: xs(:), ys(:)              !! the grids on the chosen axes
        real(dp), intent(in) :: p, theta_c                !! rigid p (rad/s), theta_c (rad)
        integer, intent(in) :: classes(:, :)              !! size(ys) x size(xs)
        real(dp), allocatable, intent(out) :: table(:, :)
        integer, intent(in), optional :: classes_b(:, :), diff(:, :)
        integer :: i, j, row
        allocate(table(size(ys) * size(xs), merge(7, 5, present(classes_b))))
        row = 0
        do i = 1, size(ys)
            do j = 1, size(xs)
                row = row + 1
                table(row, 1:4) = map_axes_row(axes_code, xs(j), ys(i), p, theta_c)
                table(row, 5) = real(classes(i, j), dp)
                if (present(classes_b)) table(row, 6:7) = [real(classes_b(i, j), dp), &
                                                           real(diff(i, j), dp)]
            end do
        end do
    end subroutine map_table

    !> Start the clock of a map; `timing`: the lines also give the elapsed time and the
    !> time left (default .false.: "map: row i/n" alone).
    subroutine progress_start(self, timing)
        class(progress_t), intent(inout) :: self
        logical, intent(in), optional :: timing
        call system_clock(self%c_start, self%rate)
        self%c_last = self%c_start
        self%printed = .false.
        self%timing = .false.
        if (present(timing)) self%timing = timing
    end subroutine progress_start

    !> After row i of n: "map: row i/n" (with timing: "map: row i/n, 12 s elapsed, about
    !> 30 s left", the rows left at the mean time per row so far) once the map has run
    !> progress_after seconds, then at most every progress_every seconds (not after the last
    !> row). Short maps stay silent.
    subroutine progress_row(self, i, n)
        class(progress_t), intent(inout) :: self
        integer, intent(in) :: i, n
        integer(int64) :: c_now
        real(dp) :: elapsed, rate
        call system_clock(c_now)
        rate = real(max(self%rate, 1_int64), dp)
        elapsed = real(c_now - self%c_start, dp) / rate
        if (i < n .and. elapsed >= progress_after .and. (.not. self%printed .or. &
            real(c_now - self%c_last, dp) / rate >= progress_every)) then
            if (self%timing) then
                write(error_unit, '(a, i0, a, i0, a, i0, a, i0, a)') 'map: row ', i, '/', n, &
                    ', ', nint(elapsed), ' s elapsed, about ', &
                    nint(elapsed / real(max(i, 1), dp) * real(n - i, dp)), ' s left'
            else
                write(error_unit, '(a, i0, a, i0)') 'map: row ', i, '/', n
            end if
            flush(error_unit)
            self%c_last = c_now
            self%printed = .true.
        end if
    end subroutine progress_row

    !> "map: row n/n (done)" if a progress line was printed.
    subroutine progress_done(self, n)
        class(progress_t), intent(in) :: self
        integer, intent(in) :: n
        if (.not. self%printed) return
        write(error_unit, '(a, i0, a, i0, a)') 'map: row ', n, '/', n, ' (done)'
        flush(error_unit)
    end subroutine progress_done

    ! ------------------------------------------------------------------------------
    ! A block under one record
    ! ------------------------------------------------------------------------------

    !> Rock `blk` under each record of &records (driver_records' load_record: read, turn
    !> over, scale; accel in g, g its unit in m/s2): what happened to each (outs, failed),
    !> its run, and with `history` the history rows of rock_on_record stacked (hlabels:
    !> the record's name per row; one row of NaN for a record that failed). A record that
    !> fails is reported on stderr at once ("<where>files(i) = '...': message"; a kv that
    !> lifts the block off is named as "&<tag>: kv = ..."), and the others go on.
    !> grid_msg /= '': the grid of the history of record ir_grid cannot be built (an
    !> input error; the records after it are not run).
    subroutine rock_records(where, tag, recs, slammer_rounding, blk, g, kv, t_max, rtol, &
                            history, t_end, dt, npts, outs, failed, runs, hist, hlabels, &
                            grid_msg, ir_grid)
        character(len=*), intent(in) :: where             !! "file:line: &records: "
        character(len=*), intent(in) :: tag               !! the analysis and its group
        type(record_in_t), intent(in) :: recs(:)
        logical, intent(in) :: slammer_rounding
        type(rocking_block_t), intent(in) :: blk
        real(dp), intent(in) :: g, kv, t_max, rtol        !! m/s2, -, s, -
        logical, intent(in) :: history
        real(dp), intent(in) :: t_end, dt                 !! history grid (s)
        integer, intent(in) :: npts
        type(record_out_t), allocatable, intent(out) :: outs(:)
        logical, allocatable, intent(out) :: failed(:)
        type(rocking_run_t), allocatable, intent(out) :: runs(:)
        real(dp), allocatable, intent(out) :: hist(:, :)  !! (t, a_g, theta, omega)
        character(len=256), allocatable, intent(out) :: hlabels(:)
        character(len=:), allocatable, intent(out) :: grid_msg
        integer, intent(out) :: ir_grid
        real(dp), allocatable :: accel(:), part(:, :)
        character(len=4096) :: msg
        real(dp) :: nan
        integer :: nrec, ir, i, st

        nan = ieee_value(nan, ieee_quiet_nan)
        nrec = size(recs)
        allocate(outs(nrec), failed(nrec), runs(nrec), hlabels(0), hist(0, 4))
        grid_msg = ''
        ir_grid = 0
        do ir = 1, nrec
            call load_record(where, recs(ir), ir, nrec, tag, slammer_rounding, outs(ir), &
                             accel)
            failed(ir) = .not. outs(ir)%ok
            if (outs(ir)%ok) then
                msg = ''
                call rock_on_record(blk, accel, outs(ir)%dt, g, kv, t_max, rtol, history, &
                                    t_end, dt, npts, runs(ir), part, st, msg, grid_msg)
                if (len(grid_msg) > 0) then
                    ir_grid = ir
                    return
                end if
                if (st == SEISPULSE_SUCCESS) then
                    if (history) then
                        hist = stack(hist, part)
                        hlabels = [character(len=256) :: hlabels, &
                                   (outs(ir)%name, i = 1, size(part, 1))]
                    end if
                    cycle
                end if
                failed(ir) = .true.
                ! the vertical record is kv times this one: the key at fault is kv
                if (index(msg, 'accel_v') == 1) msg = '&'//tag//': kv = '//real_str(kv) &
                    //': a_v = kv a_g falls below -g in this record: '//trim(msg)
                outs(ir)%message = trim(msg)
                call report(where//record_place(ir, recs(ir))//': ' &
                            //trim(msg))
            end if
            ! a failed record: one row of NaN in the history
            if (history) then
                hist = stack(hist, reshape([(nan, i = 1, 4)], [1, 4]))
                hlabels = [character(len=256) :: hlabels, outs(ir)%name]
            end if
        end do
    end subroutine rock_records

    !> Rock `blk` under one record (accel in g at (i - 1) step, linear in between, 0 after
    !> the last; g: its unit, m/s2), with the vertical ground acceleration a_v = kv a_g
    !> (kv = 0: none). With `history`, also the rows (t, a_g (m/s2), theta, omega) on the
    !> grid of t_end, dt, npts (driver_pulse_group's time_grid; t_end NaN: up to 1.25 x
    !> the end of the motion, at least the end of the record, or the time limit).
    !> stat /= SEISPULSE_SUCCESS: the library's message in msg (the record fails);
    !> grid_msg /= '': the grid of the history cannot be built (an input error).
    subroutine rock_on_record(blk, accel, step, g, kv, t_max, rtol, history, t_end, dt, &
                              npts, run, rows, stat, msg, grid_msg)
        type(rocking_block_t), intent(in) :: blk
        real(dp), intent(in) :: accel(:)                  !! the record (g)
        real(dp), intent(in) :: step, g, kv               !! s, m/s2, -
        real(dp), intent(in) :: t_max, rtol               !! run limits (s, -)
        logical, intent(in) :: history                    !! also the history rows
        real(dp), intent(in) :: t_end, dt                 !! history grid (s)
        integer, intent(in) :: npts                       !! history grid points
        type(rocking_run_t), intent(out) :: run
        real(dp), allocatable, intent(out) :: rows(:, :)  !! (t, a_g, theta, omega)
        integer, intent(out) :: stat
        character(len=*), intent(inout) :: msg
        character(len=:), allocatable, intent(out) :: grid_msg
        real(dp), allocatable :: av(:), t(:)
        real(dp) :: t_last

        grid_msg = ''
        ! a_v = kv a_g; not allocated (kv = 0): no vertical record (not present)
        if (abs(kv) > 0.0_dp) av = kv * accel
        call rock_record(blk, accel, step, g, run, stat, msg, t_max=t_max, rtol=rtol, &
                         accel_v=av)
        if (stat /= SEISPULSE_SUCCESS .or. .not. history) return
        t_last = t_end
        if (ieee_is_nan(t_end)) then
            if (run%outcome == ROCK_RUN_TIME_LIMIT .and. run%t_end > 0.0_dp) then
                t_last = run%t_end               ! no solution beyond it
            else
                t_last = max(1.25_dp * run%t_end, step * real(size(accel) - 1, dp))
            end if
        end if
        call time_grid(t_last, dt, npts, t, grid_msg)
        if (len(grid_msg) > 0) return
        allocate(rows(size(t), 4))
        rows(:, 1) = t
        rows(:, 2) = g * record_at(accel, step, t)
        call rock_record(blk, accel, step, g, run, stat, msg, t_grid=t, &
                         theta_grid=rows(:, 3), omega_grid=rows(:, 4), t_max=t_max, &
                         rtol=rtol, accel_v=av)
    end subroutine rock_on_record

    !> The record (samples accel(i) at (i - 1) dt, linear in between, 0 after the last,
    !> as the integrator takes it) at the times t (s); in the unit of the record.
    pure function record_at(accel, step, t) result(a)
        real(dp), intent(in) :: accel(:), step, t(:)
        real(dp) :: a(size(t))
        real(dp) :: x
        integer :: i, k, n
        n = size(accel)
        do i = 1, size(t)
            x = t(i) / step
            k = int(x) + 1                     ! sample at or before t(i)
            if (k >= n) then
                a(i) = 0.0_dp
                if (k == n .and. .not. x > real(n - 1, dp)) a(i) = accel(n)
            else
                a(i) = accel(k) + (accel(k + 1) - accel(k)) * (x - real(k - 1, dp))
            end if
        end do
    end function record_at

    !> Column kinds (write_tables) of a run summary of ncol columns: column j_outcome
    !> holds an outcome code, written by its name, column j_count a count (an integer).
    pure function run_summary_kinds(ncol, j_outcome, outcome_names, j_count) result(kinds)
        integer, intent(in) :: ncol, j_outcome, j_count
        character(len=*), intent(in) :: outcome_names(0:)   !! the name of each code
        character(len=:), allocatable :: kinds(:)
        character(len=:), allocatable :: outcome
        outcome = category_kind(outcome_names)
        allocate(character(len=len(outcome)) :: kinds(ncol))
        kinds = ''
        kinds(j_outcome) = outcome
        kinds(j_count) = 'int'
    end function run_summary_kinds

end module driver_rocking_common
