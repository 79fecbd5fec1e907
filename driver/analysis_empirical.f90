!> Analysis 'empirical': SLAMMER's simplified (empirical) displacement models
!> (doc/empirical.md), one row per case, yield acceleration ky and model.
!>
!> Group &empirical: the yields ky(:) (g) and the inputs of the models. Without &records
!> the cases are given: pga(:) (g), pgv(:) (cm/s), arias(:) (m/s), magnitude(:), ts(:)
!> (s), sa_15ts(:) (g, Sa(1.5 Ts) at 5 % damping), tm(:) (s), each one value (all cases)
!> or one per case; every model whose inputs are all given is tabulated. With &records
!> (driver_records) each record is a case: its own PGA, PGV, Arias intensity, mean period
!> Tm and Sa(1.5 Ts) (seispulse_intensity) feed the models, magnitude and ts are given
!> (one value or one per record), and the rigorous rigid-block result of the record
!> (newmark_rigid, exact and SLAMMER's rule, the record as scaled, downslope) stands in
!> every row next to the estimates. Table <output>_empirical. A record without energy
!> (PGA = 0 or Arias intensity 0) gives disp 0 (no sliding) in every row. A record that
!> cannot be read fails its rows (NaN, status failed) and the driver exits with status 1.
module driver_empirical
    use, intrinsic :: iso_fortran_env, only: output_unit
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan, ieee_is_nan
    use seispulse, only: dp, shortest_str, SEISPULSE_SUCCESS, int_str, empirical_rigid, &
                         empirical_needs, &
                         empirical_model_name, empirical_check, bray_travasarou_2007, &
                         rathje_antonakos_2011, probability_of_failure, EMP_RIGID_MODELS, &
                         EMP_LOG10, EMP_RA11_PGA_M, EMP_RA11_PGA_PGV, EMP_NEED_PGA, &
                         EMP_NEED_PGV, EMP_NEED_ARIAS, EMP_NEED_M, BT07_TS_RIGID, intensity_t, &
                         record_intensity, spectral_acceleration, newmark_block_t, &
                         newmark_result_t, newmark_rigid, NEWMARK_DOWN, NEWMARK_EXACT, &
                         NEWMARK_SLAMMER, finite_positive
    use driver_namelist_scan, only: nml_group
    use driver_input, only: find_group, located, given, list_length, value_name, &
                            ROWS_FAILED
    use driver_input, only: missing_group
    use driver_input, only: output_located
    use driver_tables, only: write_tables, say_written, category_kind, status_names
    use driver_records, only: records_keys, record_in_t, record_out_t, records_defaults, &
                              read_records, check_records, echo_records, load_record, report, &
                              record_line, failed_records
    use driver_echo, only: echo_unit
    implicit none
    private

    public :: run_empirical, empirical_groups, empirical_tables

    !> Groups this analysis reads (besides &run).
    character(len=9), parameter :: empirical_groups(2) = [character(len=9) :: 'records', &
        'empirical']

    !> Tables this analysis may write (removed with the echo file after an input error).
    character(len=9), parameter :: empirical_tables(1) = [character(len=9) :: 'empirical']

    character(len=12), parameter :: empirical_keys(11) = [character(len=12) :: 'ky', 'pga', &
        'pgv', 'arias', 'magnitude', 'ts', 'sa_15ts', 'tm', 'slammer', 'damping', 'g']

    !> The inputs of a case, in this order (key names of &empirical).
    integer, parameter :: NIN = 7
    integer, parameter :: IN_PGA = 1, IN_PGV = 2, IN_ARIAS = 3, IN_M = 4, IN_TS = 5, &
                          IN_SA = 6, IN_TM = 7
    !> Need bits of the driver's own inputs, above the library's EMP_NEED_* (1, 2, 4, 8).
    integer, parameter :: NEED_TS = 16, NEED_SA = 32, NEED_TM = 64
    character(len=9), parameter :: in_keys(NIN) = [character(len=9) :: 'pga', 'pgv', 'arias', &
        'magnitude', 'ts', 'sa_15ts', 'tm']
    !> The names empirical_check knows them by.
    character(len=9), parameter :: check_names(NIN) = [character(len=9) :: 'pga', 'pgv', &
        'arias', 'magnitude', 'ts', 'sa', 'tm']

    !> Rows per case and ky: the rigid-block models, then these three.
    integer, parameter :: M_BT07 = EMP_RIGID_MODELS + 1, M_RA11_M = EMP_RIGID_MODELS + 2, &
                          M_RA11_PGV = EMP_RIGID_MODELS + 3, NMODEL = EMP_RIGID_MODELS + 3

    !> Numeric columns of the table (after the label, the model's name).
    integer, parameter :: NCOL = 20
    integer, parameter :: C_CASE = 1, C_KY = 2, C_IN = 2, C_DISP = 10, C_SIGMA = 11, &
                          C_BASE = 12, C_D16 = 13, C_D84 = 14, C_PZERO = 15, C_PFAIL = 16, &
                          C_KMAX = 17, C_EXACT = 18, C_SLAMMER = 19, C_STATUS = 20

    integer, parameter :: max_list = 1000

    ! namelist variables (defaults in set_defaults)
    real(dp) :: ky(max_list), pga(max_list), pgv(max_list), arias(max_list), &
                magnitude(max_list), ts(max_list), sa_15ts(max_list), tm(max_list)
    real(dp) :: damping, g
    logical :: slammer
    namelist /empirical/ ky, pga, pgv, arias, magnitude, ts, sa_15ts, tm, slammer, damping, g

    !> The validated input.
    type :: config_t
        type(record_in_t), allocatable :: recs(:)
        logical :: with_records = .false.
        logical :: slammer_rounding = .false.
        real(dp), allocatable :: ky(:)
        real(dp), allocatable :: inputs(:, :)   !! case x NIN (NaN: not given)
        integer :: ncase = 0
        logical :: slammer = .false.
        real(dp) :: damping = 0.05_dp
        real(dp) :: g = 9.80665_dp
    end type config_t

contains

    subroutine set_defaults()
        real(dp) :: nan
        nan = ieee_value(nan, ieee_quiet_nan)
        call records_defaults()
        ky = nan
        pga = nan
        pgv = nan
        arias = nan
        magnitude = nan
        ts = nan
        sa_15ts = nan
        tm = nan
        slammer = .false.
        damping = 0.05_dp
        g = 9.80665_dp
    end subroutine set_defaults

    subroutine read_empirical(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        if (len(text) > 0) then
            read(text, nml=empirical, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=empirical, iostat=ios, iomsg=iomsg)
        end if
    end subroutine read_empirical

    !> Read and check the groups, compute every row, write the table. stat: 0,
    !> ROWS_FAILED (table written, some records failed), or > 0 (nothing written).
    subroutine run_empirical(path, groups, prefix, stat, errmsg)
        character(len=*), intent(in) :: path              !! input file (for messages)
        type(nml_group), intent(in) :: groups(:)          !! scanned groups
        character(len=*), intent(in) :: prefix            !! output prefix
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        type(nml_group) :: gr, ge
        type(config_t) :: cfg
        type(record_out_t), allocatable :: outs(:)
        real(dp), allocatable :: table(:, :)
        character(len=32), allocatable :: labels(:)
        character(len=512) :: files_out(2)
        character(len=:), allocatable :: named
        integer :: nfailed, ir

        call set_defaults()
        call read_optional_group('records', records_keys, read_records, gr)
        if (stat /= 0) return
        call read_optional_group('empirical', empirical_keys, read_empirical, ge)
        if (stat /= 0) return
        stat = 1
        if (find_group(groups, 'empirical') == 0) then
            errmsg = missing_group(path, 'empirical')//' (it gives the yield accelerations ' &
                     //'ky and the models'' inputs)'
            return
        end if
        cfg%with_records = find_group(groups, 'records') > 0
        if (cfg%with_records) then
            call check_records(path, gr, cfg%recs, cfg%slammer_rounding, errmsg)
            if (len(errmsg) > 0) return
        end if
        call check_empirical(path, ge, cfg, errmsg)
        if (len(errmsg) > 0) return

        if (cfg%with_records) call echo_records(cfg%recs, cfg%slammer_rounding)
        call echo_empirical(cfg)

        call compute(path, gr, cfg, outs, table, labels, nfailed)

        call write_result(path, prefix, cfg, outs, table, labels, files_out, stat, errmsg)
        if (stat /= 0) then
            stat = 1
            errmsg = output_located(path)//errmsg
            return
        end if
        call say_written('empirical table', files_out)
        stat = 0
        if (nfailed > 0) then
            stat = ROWS_FAILED
            errmsg = int_str(nfailed)//' of '//int_str(size(table, 1))//' rows failed'
            if (cfg%with_records) then
                ! the records with a failed row (read or not)
                named = failed_records(outs, [(any(table(:, C_STATUS) > 0.5_dp .and. &
                                                   nint(table(:, C_CASE)) == ir), &
                                               ir = 1, size(outs))])
                if (len(named) > 0) errmsg = errmsg//' (records: '//named//')'
            end if
        end if

    contains

        subroutine read_optional_group(name, keys, reader, group)
            use driver_input, only: read_optional, group_reader
            character(len=*), intent(in) :: name, keys(:)
            procedure(group_reader) :: reader
            type(nml_group), intent(out) :: group
            call read_optional(path, groups, name, keys, reader, group, stat, errmsg)
        end subroutine read_optional_group

    end subroutine run_empirical

    ! ------------------------------------------------------------------------------
    ! Checks
    ! ------------------------------------------------------------------------------

    !> Check &empirical and fill cfg. errmsg is empty on success.
    subroutine check_empirical(path, ge, cfg, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: ge
        type(config_t), intent(inout) :: cfg
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: where
        character(len=512) :: msg
        integer :: n, i, k, c, counts(NIN), st
        real(dp) :: nan, x

        nan = ieee_value(nan, ieee_quiet_nan)
        where = located(path, ge)
        errmsg = ''
        if (.not. finite_positive(g)) then
            errmsg = where//'g = '//shortest_str(g)//': must be a finite number > 0 (m/s2)'
            return
        end if
        cfg%g = g
        if (.not. (damping >= 0.0_dp .and. damping < 1.0_dp)) then
            errmsg = where//'damping = '//shortest_str(damping) &
                //': must be in [0, 1) (the damping ' &
                     //'ratio of Sa(1.5 Ts), 0.05 in the models)'
            return
        end if
        cfg%damping = damping
        cfg%slammer = slammer

        ! --- ky
        if (.not. given(ge, 'ky')) then
            errmsg = where//'ky: missing (the yield accelerations, g)'
            return
        end if
        call list_length(ky, 'ky', n, errmsg)
        if (len(errmsg) > 0) then
            errmsg = where//errmsg
            return
        end if
        do i = 1, n
            msg = ''
            call empirical_check('ky', ky(i), st, msg)
            if (st /= SEISPULSE_SUCCESS) then
                errmsg = where//value_name('ky', i, n)//rest(msg)
                return
            end if
        end do
        cfg%ky = ky(1:n)

        ! --- the inputs: how many values each (0: not given)
        counts = 0
        do k = 1, NIN
            if (.not. given(ge, trim(in_keys(k)))) cycle
            if (cfg%with_records .and. .not. (k == IN_M .or. k == IN_TS)) then
                errmsg = where//trim(in_keys(k))//': not with &records (each record''s ' &
                         //'own '//trim(in_keys(k))//' is used; give magnitude and ts only)'
                return
            end if
            call list_length(column(k), trim(in_keys(k)), counts(k), errmsg)
            if (len(errmsg) > 0) then
                errmsg = where//errmsg
                return
            end if
        end do
        if (cfg%with_records) then
            cfg%ncase = size(cfg%recs)
        else
            cfg%ncase = max(1, maxval(counts))
            if (all(counts == 0)) then
                errmsg = where//'pga, pgv, arias, magnitude, ts, sa_15ts, tm: none given ' &
                         //'(give the inputs of the models, or the records in &records)'
                return
            end if
        end if
        allocate(cfg%inputs(cfg%ncase, NIN))
        cfg%inputs = nan
        do k = 1, NIN
            if (counts(k) == 0) cycle
            if (counts(k) > 1 .and. counts(k) /= cfg%ncase) then
                errmsg = where//trim(in_keys(k))//': '//int_str(counts(k))//' values for ' &
                         //int_str(cfg%ncase)//' '//trim(merge('records', 'cases  ', &
                         cfg%with_records))//' (give one value for all, or one each)'
                return
            end if
            do c = 1, cfg%ncase
                x = column_value(k, min(c, counts(k)))
                msg = ''
                call empirical_check(trim(check_names(k)), x, st, msg)
                if (st /= SEISPULSE_SUCCESS) then
                    errmsg = where//value_name(trim(in_keys(k)), min(c, counts(k)), &
                                               counts(k))//rest(msg)
                    return
                end if
                cfg%inputs(c, k) = x
            end do
        end do

    contains

        !> The list of input k.
        function column(k) result(v)
            integer, intent(in) :: k
            real(dp) :: v(max_list)
            select case (k)
            case (IN_PGA)
                v = pga
            case (IN_PGV)
                v = pgv
            case (IN_ARIAS)
                v = arias
            case (IN_M)
                v = magnitude
            case (IN_TS)
                v = ts
            case (IN_SA)
                v = sa_15ts
            case default
                v = tm
            end select
        end function column

        real(dp) function column_value(k, i)
            integer, intent(in) :: k, i
            real(dp) :: v(max_list)
            v = column(k)
            column_value = v(i)
        end function column_value

        !> " = value: must be ..." of a library message "name = value: must be ...".
        function rest(text) result(r)
            character(len=*), intent(in) :: text
            character(len=:), allocatable :: r
            integer :: j
            j = index(text, ' = ')
            r = trim(text(j:))
        end function rest

    end subroutine check_empirical

    !> &empirical with the keys in use.
    subroutine echo_empirical(cfg)
        type(config_t), intent(in) :: cfg
        call echo_n(size(cfg%ky), cfg%ncase)

    contains

        subroutine echo_n(n, nc)
            integer, intent(in) :: n, nc
            real(dp) :: ky(n), pga(nc), pgv(nc), arias(nc), magnitude(nc), ts(nc), &
                        sa_15ts(nc), tm(nc), damping, g
            logical :: slammer
            namelist /empirical/ ky, pga, pgv, arias, magnitude, ts, sa_15ts, tm, slammer, &
                damping, g
            ky = cfg%ky
            pga = cfg%inputs(:, IN_PGA)
            pgv = cfg%inputs(:, IN_PGV)
            arias = cfg%inputs(:, IN_ARIAS)
            magnitude = cfg%inputs(:, IN_M)
            ts = cfg%inputs(:, IN_TS)
            sa_15ts = cfg%inputs(:, IN_SA)
            tm = cfg%inputs(:, IN_TM)
            slammer = cfg%slammer
            damping = cfg%damping
            g = cfg%g
            write(echo_unit(), nml=empirical)
        end subroutine echo_n

    end subroutine echo_empirical

    ! ------------------------------------------------------------------------------
    ! Computation
    ! ------------------------------------------------------------------------------

    !> The inputs besides ky of row model m (EMP_NEED_* and NEED_* bits).
    pure integer function needs_of(m) result(nd)
        integer, intent(in) :: m
        select case (m)
        case (M_BT07)
            nd = NEED_TS + NEED_SA + EMP_NEED_M
        case (M_RA11_M)
            nd = NEED_TS + NEED_TM + EMP_NEED_PGA + EMP_NEED_M
        case (M_RA11_PGV)
            nd = NEED_TS + NEED_TM + EMP_NEED_PGA + EMP_NEED_PGV
        case default
            nd = empirical_needs(m)
        end select
    end function needs_of

    !> The row label of model m.
    pure function model_label(m) result(s)
        integer, intent(in) :: m
        character(len=:), allocatable :: s
        select case (m)
        case (M_BT07)
            s = 'bray_travasarou_2007'
        case (M_RA11_M)
            s = 'rathje_antonakos_2011_m'
        case (M_RA11_PGV)
            s = 'rathje_antonakos_2011_pgv'
        case default
            s = empirical_model_name(m)
        end select
    end function model_label

    !> The bits of the inputs a case has (not NaN).
    pure integer function have_of(inp) result(h)
        real(dp), intent(in) :: inp(NIN)
        h = 0
        if (.not. ieee_is_nan(inp(IN_PGA))) h = h + EMP_NEED_PGA
        if (.not. ieee_is_nan(inp(IN_PGV))) h = h + EMP_NEED_PGV
        if (.not. ieee_is_nan(inp(IN_ARIAS))) h = h + EMP_NEED_ARIAS
        if (.not. ieee_is_nan(inp(IN_M))) h = h + EMP_NEED_M
        if (.not. ieee_is_nan(inp(IN_TS))) h = h + NEED_TS
        if (.not. ieee_is_nan(inp(IN_SA))) h = h + NEED_SA
        if (.not. ieee_is_nan(inp(IN_TM))) h = h + NEED_TM
    end function have_of

    !> Every case (a record: read, intensity measures, rigorous rigid block), every ky,
    !> every model with its inputs.
    subroutine compute(path, gr, cfg, outs, table, labels, nfailed)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gr
        type(config_t), intent(inout) :: cfg
        type(record_out_t), allocatable, intent(out) :: outs(:)
        real(dp), allocatable, intent(out) :: table(:, :)
        character(len=32), allocatable, intent(out) :: labels(:)
        integer, intent(out) :: nfailed
        real(dp), allocatable :: accel(:), rows(:, :), exact(:), slam(:)
        character(len=32), allocatable :: lab(:)
        character(len=:), allocatable :: where
        type(intensity_t) :: im
        type(newmark_block_t) :: blk
        type(newmark_result_t) :: res
        character(len=4096) :: msg
        real(dp) :: nan, inp(NIN), sa
        integer :: c, i, m, n, have, st, nky
        logical :: ok, still

        nan = ieee_value(nan, ieee_quiet_nan)
        where = located(path, gr)
        nky = size(cfg%ky)
        allocate(outs(cfg%ncase), exact(nky), slam(nky))
        allocate(rows(cfg%ncase * nky * NMODEL, NCOL), lab(cfg%ncase * nky * NMODEL))
        n = 0
        nfailed = 0
        do c = 1, cfg%ncase
            inp = cfg%inputs(c, :)
            exact = nan
            slam = nan
            ok = .true.
            if (cfg%with_records) then
                call load_record(where, cfg%recs(c), c, cfg%ncase, 'empirical', &
                                 cfg%slammer_rounding, outs(c), accel)
                ok = outs(c)%ok
                if (ok) then
                    msg = ''
                    call record_intensity(accel, outs(c)%dt, cfg%g, im, st, msg)
                    if (st == SEISPULSE_SUCCESS) then
                        inp(IN_PGA) = im%pga
                        inp(IN_PGV) = 100.0_dp * im%pgv
                        inp(IN_ARIAS) = im%arias
                        inp(IN_TM) = im%tm
                        if (.not. ieee_is_nan(inp(IN_TS))) then
                            if (inp(IN_TS) < BT07_TS_RIGID) then
                                inp(IN_SA) = im%pga       ! doc/empirical.md (E.14)
                            else
                                call spectral_acceleration(accel, outs(c)%dt, &
                                    1.5_dp * inp(IN_TS), cfg%damping, cfg%g, sa, st, msg)
                                inp(IN_SA) = sa
                            end if
                        end if
                    end if
                    if (st /= SEISPULSE_SUCCESS) call fail_record(trim(msg))
                end if
                if (ok) then
                    ! the rigorous rigid block, downslope, the record as scaled
                    do i = 1, nky
                        blk%mode = NEWMARK_DOWN
                        blk%ky = cfg%ky(i)
                        blk%ky_up = cfg%ky(i)
                        call newmark_rigid(accel, outs(c)%dt, blk, NEWMARK_EXACT, cfg%g, res, &
                                           st, msg)
                        if (st == SEISPULSE_SUCCESS) exact(i) = 100.0_dp * res%max_disp
                        if (st == SEISPULSE_SUCCESS) call newmark_rigid(accel, outs(c)%dt, &
                            blk, NEWMARK_SLAMMER, cfg%g, res, st, msg)
                        if (st == SEISPULSE_SUCCESS) slam(i) = 100.0_dp * res%max_disp
                        if (st /= SEISPULSE_SUCCESS) then
                            call fail_record(trim(msg))
                            exit
                        end if
                    end do
                end if
                cfg%inputs(c, :) = inp
            end if
            have = have_of(inp)
            ! a record gives PGA, PGV, Ia, Sa and Tm itself (NaN when it failed, and Tm
            ! when no frequency of its band carries energy): the given inputs decide
            if (cfg%with_records) have = ior(have, EMP_NEED_PGA + EMP_NEED_PGV &
                                                  + EMP_NEED_ARIAS + NEED_SA + NEED_TM)
            ! a record without energy: no sliding in any model
            still = cfg%with_records .and. ok .and. &
                    .not. (inp(IN_PGA) > 0.0_dp .and. inp(IN_ARIAS) > 0.0_dp)
            do i = 1, nky
                do m = 1, NMODEL
                    if (iand(needs_of(m), have) /= needs_of(m)) cycle
                    n = n + 1
                    lab(n) = model_label(m)
                    rows(n, :) = nan
                    rows(n, C_CASE) = real(c, dp)
                    rows(n, C_KY) = cfg%ky(i)
                    rows(n, C_IN + 1:C_IN + NIN) = inp
                    rows(n, C_EXACT) = exact(i)
                    rows(n, C_SLAMMER) = slam(i)
                    rows(n, C_STATUS) = 1.0_dp
                    if (.not. ok) then
                        nfailed = nfailed + 1
                        cycle
                    end if
                    if (still) then
                        call no_sliding(rows(n, :))
                        if (m == M_BT07) rows(n, C_PZERO) = 1.0_dp
                        cycle
                    end if
                    call model_row(m, cfg%ky(i), inp, cfg%slammer, rows(n, :))
                    if (rows(n, C_STATUS) > 0.5_dp) nfailed = nfailed + 1
                end do
            end do
        end do
        table = rows(1:n, :)
        labels = lab(1:n)

    contains

        subroutine fail_record(text)
            character(len=*), intent(in) :: text
            ok = .false.
            outs(c)%ok = .false.
            outs(c)%message = text
            call report(where//'files('//int_str(c)//') = '''//cfg%recs(c)%file//''': ' &
                        //text)
        end subroutine fail_record

    end subroutine compute

    !> One row of model m: disp, sigma, base, d16, d84 (and p_zero, kmax), p_failure,
    !> status 0. A ratio model with ky >= PGA: 0 (a rigid block does not slide).
    subroutine model_row(m, ky, inp, sl, row)
        integer, intent(in) :: m
        real(dp), intent(in) :: ky, inp(NIN)
        logical, intent(in) :: sl
        real(dp), intent(inout) :: row(NCOL)
        real(dp) :: d, s, p0, km, kv, dr, f
        integer :: base, st, form
        character(len=512) :: msg
        base = 1
        p0 = ieee_value(p0, ieee_quiet_nan)
        km = p0
        msg = ''
        select case (m)
        case (M_BT07)
            call bray_travasarou_2007(ky, inp(IN_TS), inp(IN_SA), inp(IN_M), d, s, p0, st, &
                                      msg, slammer=sl)
        case (M_RA11_M, M_RA11_PGV)
            if (ieee_is_nan(inp(IN_TM))) then
                ! a record whose band 0.25-20 Hz carries no energy (doc/intensity.md)
                call report('empirical: '//model_label(m)//', ky = '//shortest_str(ky)//': tm = ' &
                            //'NaN: the record has no mean period (no Fourier amplitude ' &
                            //'at 0.25-20 Hz)')
                return
            end if
            form = merge(EMP_RA11_PGA_M, EMP_RA11_PGA_PGV, m == M_RA11_M)
            call rathje_antonakos_2011(form, ky, inp(IN_TS), inp(IN_TM), inp(IN_PGA), &
                                       inp(IN_PGV), inp(IN_M), d, s, km, kv, dr, st, msg, &
                                       slammer=sl)
        case default
            if (iand(empirical_needs(m), EMP_NEED_PGA) /= 0 .and. .not. ky < inp(IN_PGA)) then
                call no_sliding(row)
                return
            end if
            call empirical_rigid(m, ky, inp(IN_PGA), inp(IN_PGV), inp(IN_ARIAS), inp(IN_M), &
                                 d, s, base, st, msg)
        end select
        if (st /= SEISPULSE_SUCCESS) then
            call report('empirical: '//model_label(m)//', ky = '//shortest_str(ky)//': '//trim(msg))
            return
        end if
        row(C_BASE) = merge(10.0_dp, exp(1.0_dp), base == EMP_LOG10)
        f = row(C_BASE)**s
        row(C_DISP) = d
        row(C_SIGMA) = s
        row(C_D16) = d / f
        row(C_D84) = d * f
        row(C_PZERO) = p0
        row(C_PFAIL) = probability_of_failure(d)
        row(C_KMAX) = km
        row(C_STATUS) = 0.0_dp
    end subroutine model_row

    !> A row of no sliding: disp, d16, d84 and p_failure 0, status 0 (sigma as it was).
    pure subroutine no_sliding(row)
        real(dp), intent(inout) :: row(NCOL)
        row(C_DISP) = 0.0_dp
        row(C_D16) = 0.0_dp
        row(C_D84) = 0.0_dp
        row(C_PFAIL) = 0.0_dp
        row(C_STATUS) = 0.0_dp
    end subroutine no_sliding

    ! ------------------------------------------------------------------------------
    ! Output
    ! ------------------------------------------------------------------------------

    subroutine write_result(path, prefix, cfg, outs, table, labels, files_out, stat, errmsg)
        character(len=*), intent(in) :: path, prefix
        type(config_t), intent(in) :: cfg
        type(record_out_t), intent(in) :: outs(:)
        real(dp), intent(in) :: table(:, :)
        character(len=*), intent(in) :: labels(:)
        character(len=*), intent(out) :: files_out(2)
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=4096), allocatable :: comments(:)
        character(len=16) :: names(NCOL + 1), col_units(NCOL + 1), kinds(NCOL + 1)
        character(len=:), allocatable :: line
        integer :: c, nc

        nc = 9
        if (cfg%with_records) nc = nc + 1 + size(outs)
        allocate(comments(nc))
        comments(1) = 'seispulse analysis empirical: simplified (empirical) estimates of the ' &
                      //'permanent slope displacement (doc/empirical.md), one row per case, ky ' &
                      //'and model'
        comments(2) = 'input: '//trim(path)
        comments(3) = 'models: jibson_1993 [J93], jibson_1998 [J98], jibson_2007_* [J07], ' &
                      //'ambraseys_menu_1988 [AM88], saygili_rathje_2008_* [SR08], ' &
                      //'rathje_saygili_2009 [RS09], bray_travasarou_2007 [BT07], ' &
                      //'rathje_antonakos_2011_m/_pgv [RA11]; a model is tabulated when ' &
                      //'all its inputs are given'
        comments(4) = 'disp: median (cm); sigma: standard deviation of log D in base `base` ' &
                      //'(10 or e, as the source); d16, d84 = disp / base^sigma, disp * ' &
                      //'base^sigma; p_failure: Jibson et al. (2000) at disp'
        comments(5) = 'bray_travasarou_2007: disp is the median non-zero displacement, ' &
                      //'p_zero = P(D <= 1 cm); rathje_antonakos_2011: kmax (g) of the ' &
                      //'sliding mass; slammer = '//trim(merge('true ', 'false', cfg%slammer)) &
                      //' (SLAMMER 1.1''s rules for these two)'
        comments(6) = 'a model of ky/PGA with ky >= PGA: disp 0 (a rigid block does not ' &
                      //'slide), sigma NaN; NaN: not applicable'
        if (cfg%with_records) comments(6) = trim(comments(6))//'; a record without ' &
            //'energy (PGA = 0 or arias = 0): disp 0 in every row (p_zero 1)'
        if (cfg%with_records) then
            comments(7) = 'cases are the records: pga (g), pgv (cm/s), arias (m/s), tm (s) ' &
                          //'and sa_15ts = Sa(1.5 ts) (g, damping '//shortest_str(cfg%damping) &
                          //'; PGA for ts < 0.05 s) are the record''s own (g = ' &
                          //shortest_str(cfg%g)//' m/s2)'
            comments(8) = 'newmark_exact, newmark_slammer: the rigorous rigid block on the ' &
                          //'record (cm, downslope, the record as scaled; exact solution and ' &
                          //'SLAMMER''s rule)'
        else
            comments(7) = 'cases: the values of &empirical (one value for all cases, or one ' &
                          //'per case)'
            comments(8) = 'newmark_exact, newmark_slammer: NaN (no records)'
        end if
        comments(9) = 'status: ok, or failed (nan results; the reason is on stderr)'
        if (cfg%with_records) then
            comments(10) = 'records (index, file, format read, npts, dt (s), PGA as read ' &
                           //'(g), scale factor):'
            do c = 1, size(outs)
                line = record_line(c, cfg%recs(c), outs(c))
                comments(10 + c) = line
            end do
        end if
        names = [character(len=16) :: 'model', 'case', 'ky', 'pga', 'pgv', 'arias', &
                 'magnitude', 'ts', 'sa_15ts', 'tm', 'disp', 'sigma', 'base', 'd16', 'd84', &
                 'p_zero', 'p_failure', 'kmax', 'newmark_exact', 'newmark_slammer', 'status']
        col_units = [character(len=16) :: '-', '-', 'g', 'g', 'cm/s', 'm/s', '-', 's', 'g', &
                     's', 'cm', '-', '-', 'cm', 'cm', '-', '-', 'g', 'cm', 'cm', '-']
        kinds = ''
        kinds(2) = 'int'
        kinds(NCOL + 1) = category_kind(status_names)
        call write_tables(prefix, 'empirical', comments, names, col_units, table, files_out, &
                          stat, errmsg, labels=labels, kinds=kinds)
    end subroutine write_result

end module driver_empirical
