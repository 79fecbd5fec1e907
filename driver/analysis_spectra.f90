!> Analysis 'spectra': code spectra side by side (EN 1998-1 types 1 and 2, with a_g given
!> or from a zone of the Greek National Annex; EAK 2000), and the check of a suite of
!> records against a code's elastic spectrum (EN 1998-1 3.2.3.1.2(4), doc/record-suites.md).
!>
!> Groups: &spectra (the period grid, as in &sdof, the codes and the kind of spectrum),
!> &ec8 and &eak (the parameters of each code, needed only when `codes` or the target
!> names them), &records (the shared group, driver_records) and &suite (the check: T1,
!> the target, the grid, the fit; `records_from` reads the &records group of another
!> input file). Tables <output>_spectra (with &spectra), and with &suite:
!> <output>_suite (one-row summary), <output>_suite_records, <output>_suite_mean,
!> <output>_suite_spectra. Everything is checked before any record is read (also that no
!> two tables get one file name); the records read are joined and checked together (the
!> library evaluates their 5 % PSA on the check grid and between grid periods). A record
!> that cannot be read or analysed fails its rows
!> (status failed; reported on stderr) and fails the check (check fail, status failed:
!> the suite checked is not the one listed); the figures are those of the others if at
!> least min_records remain (else NaN); run_spectra then returns ROWS_FAILED (exit
!> status 1). The numbers come from seispulse_codes, seispulse_eak2000,
!> seispulse_record_suite and seispulse_sdof_sim; the driver only reads, checks and
!> writes.
module driver_spectra
    use, intrinsic :: iso_fortran_env, only: error_unit
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_quiet_nan
    use seispulse, only: dp, shortest_str, g_str, SEISPULSE_SUCCESS, int_str, outside, upper, &
                         STANDARD_GRAVITY, &
                         ec8_elastic_spectrum, ec8_design_spectrum, ec8_ground_parameters, &
                         ec8_damping_correction, EC8_SPECTRUM_TYPE_1, EC8_SPECTRUM_TYPE_2, &
                         ec8_reference_pga, ec8_design_ag, EC8_ANNEX_GR, &
                         eak2000_ground_parameters, eak2000_zone_acceleration, &
                         eak2000_importance_factor, eak2000_damping_correction, &
                         eak2000_design_spectrum, eak2000_elastic_spectrum, EAK_GROUND_A, &
                         EAK_MAP_2003, EAK_MAP_2000, EAK_BETA0, &
                         suite_check_t, suite_check_periods, SUITE_FIT_LINEAR, SUITE_FIT_LOG, &
                         suite_target_t, suite_target_pga, suite_target_values, &
                         suite_target_corners, ec8_suite_check_records, suite_records_room, &
                         SUITE_TARGET_EC8, SUITE_TARGET_EAK, SUITE_RULE_PGA, &
                         SUITE_SPECTRUM_FRACTION, suite_records_grid
    use driver_namelist_scan, only: nml_group, scan_file
    use driver_input, only: find_group, check_keys, read_group, located, join, &
                            read_optional, given, list_item, name_index, ROWS_FAILED, &
                            missing_group, output_located
    use driver_tables, only: write_tables, delete_files, say_written, category_kind, &
                             status_names, table_path
    use driver_records, only: records_keys, record_in_t, record_out_t, records_defaults, &
                              read_records, check_records, echo_records, load_record, report, &
                              records_missing, record_line, failed_records, resolve, &
                              count_strings, label_len
    use driver_sdof_common, only: max_periods
    use driver_axis, only: axis_values
    use driver_echo, only: echo_unit, echo_path
    use driver_records, only: record_place
    implicit none
    private

    public :: run_spectra, spectra_groups, spectra_tables

    !> Groups this analysis reads (besides &run).
    character(len=8), parameter :: spectra_groups(5) = [character(len=8) :: 'spectra', 'ec8', &
        'eak', 'records', 'suite']

    !> Tables this analysis may write (removed with the echo file after an input error).
    character(len=13), parameter :: spectra_tables(5) = [character(len=13) :: 'spectra', &
        'suite', 'suite_records', 'suite_mean', 'suite_spectra']

    character(len=12), parameter :: spectra_keys(6) = [character(len=12) :: 'periods', &
        'period_range', 'period_count', 'spacing', 'codes', 'kind']
    character(len=14), parameter :: ec8_keys(8) = [character(len=14) :: 'ag', 'zone', &
        'national_annex', 'importance', 'ground', 'damping', 'q', 'beta']
    character(len=16), parameter :: eak_keys(12) = [character(len=16) :: 'zone', 'alpha', &
        'zone_map', 'ground', 'importance', 'importance_class', 'q', 'theta', 'damping', &
        'eta_min', 'lower_bound', 'elastic_exponent']
    character(len=12), parameter :: suite_keys(6) = [character(len=12) :: 't1', 'target', &
        'n_points', 'fit', 'min_records', 'records_from']

    !> The codes (names as written, lower case), their column stems and titles.
    integer, parameter :: CODE_EC8_1 = 1, CODE_EC8_2 = 2, CODE_EAK = 3
    character(len=5), parameter :: code_names(3) = [character(len=5) :: 'ec8_1', 'ec8_2', 'eak']
    character(len=7), parameter :: kind_names(3) = [character(len=7) :: 'elastic', 'design', &
        'both']
    character(len=5), parameter :: code_names_upper(3) = [character(len=5) :: 'EC8_1', &
        'EC8_2', 'EAK']
    character(len=6), parameter :: fit_names(2) = [character(len=6) :: 'linear', 'log']
    character(len=1), parameter :: ec8_grounds(5) = ['a', 'b', 'c', 'd', 'e']
    !> EAK ground names: A..D, and X (eak2000_ground_parameters refuses it with its reason,
    !> placed at &eak ground).
    character(len=1), parameter :: eak_grounds(5) = ['a', 'b', 'c', 'd', 'x']
    character(len=2), parameter :: ec8_zones(3) = [character(len=2) :: 'z1', 'z2', 'z3']
    character(len=3), parameter :: eak_zones_2000(4) = [character(len=3) :: 'i', 'ii', 'iii', &
        'iv']
    character(len=4), parameter :: map_names(2) = [character(len=4) :: '2003', '2000']
    character(len=3), parameter :: class_names(4) = [character(len=3) :: 'i', 'ii', 'iii', 'iv']
    character(len=2), parameter :: annex_names(1) = [character(len=2) :: 'gr']
    !> Names of the pass/fail and no/yes category columns.
    character(len=4), parameter :: check_names(0:1) = [character(len=4) :: 'fail', 'pass']
    character(len=3), parameter :: yes_names(0:1) = [character(len=3) :: 'no', 'yes']
    !> The rule that sets common_scale: (b) the PGA, (c) the spectrum.
    character(len=8), parameter :: rule_names(0:1) = [character(len=8) :: 'pga', 'spectrum']

    !> Most codes in `codes` (each once: 3), with room to find one given twice.
    integer, parameter :: max_codes = 10
    !> The largest double (no upper bound).
    real(dp), parameter :: big = huge(1.0_dp)
    !> The rule of a damping ratio (&ec8, &eak; as &sdof's).
    character(len=*), parameter :: damping_rule = 'must be a damping ratio in [0, 1) ' &
        //'(a ratio: 0.05 = 5 %)'
    !> Longest period (s) at which EN 1998-1 states the elastic spectrum.
    real(dp), parameter :: en_max_period = 4.0_dp

    ! namelist variables (defaults are set in set_defaults); &ec8 and &eak share key
    ! names: local namelists in their readers read them into c_*, k_*
    real(dp) :: periods(max_periods), period_range(2)
    integer :: period_count
    character(len=32) :: spacing, codes(max_codes), kind
    namelist /spectra/ periods, period_range, period_count, spacing, codes, kind
    real(dp) :: c_ag, c_importance, c_damping, c_q, c_beta
    character(len=32) :: c_zone, c_annex, c_ground
    real(dp) :: k_alpha, k_importance, k_q, k_theta, k_damping, k_eta_min, k_lower_bound, &
                k_exponent
    character(len=32) :: k_zone, k_zone_map, k_ground, k_class
    real(dp) :: t1
    integer :: n_points, min_records
    character(len=32) :: target, fit
    character(len=1024) :: records_from
    namelist /suite/ t1, target, n_points, fit, min_records, records_from

    !> EN 1998-1 parameters (&ec8).
    type :: ec8_t
        real(dp) :: ag = 0.0_dp             !! design ground acceleration gamma_I a_gR (g)
        integer :: zone = 0                 !! Greek NA zone 1..3, 0: ag given
        real(dp) :: agr = 0.0_dp            !! a_gR of the zone (g)
        real(dp) :: importance = 1.0_dp     !! gamma_I (with a zone)
        integer :: ground = 1               !! EC8_GROUND_A .. E
        real(dp) :: damping = 0.05_dp       !! ratio (elastic spectra)
        real(dp) :: q = 1.5_dp, beta = 0.2_dp
    end type ec8_t

    !> EAK 2000 parameters (&eak).
    type :: eak_t
        real(dp) :: alpha = 0.0_dp          !! A/g
        integer :: zone = 0                 !! zone of zone_map, 0: alpha given
        integer :: zone_map = EAK_MAP_2003
        integer :: ground = 2               !! EAK_GROUND_A .. D
        real(dp) :: importance = 1.0_dp     !! gamma_I
        integer :: importance_class = 0     !! 1..4 when given as a category
        real(dp) :: q = 1.0_dp, theta = 1.0_dp, damping = 0.05_dp, eta_min = 0.0_dp, &
                    lower_bound = 0.0_dp, exponent = 2.0_dp / 3.0_dp
    end type eak_t

    !> The validated input.
    type :: config_t
        logical :: table = .false.                  !! &spectra given: the spectra table
        real(dp), allocatable :: periods(:)         !! its periods (s)
        character(len=:), allocatable :: grid       !! how they were given
        integer, allocatable :: codes(:)            !! CODE_* in the order given
        integer :: kind = 3                         !! 1 elastic, 2 design, 3 both
        logical :: use_ec8 = .false., use_eak = .false.
        type(ec8_t) :: ec8
        type(eak_t) :: eak
        logical :: suite = .false.                  !! &suite given: the check
        real(dp) :: t1 = 0.0_dp                     !! s
        integer :: target = CODE_EC8_1
        integer :: n_points = 400
        integer :: fit = SUITE_FIT_LINEAR
        integer :: min_records = 3
        character(len=:), allocatable :: records_from   !! the other input, as opened ('' none)
        character(len=:), allocatable :: rec_path   !! the file that holds &records
        type(nml_group) :: gr                       !! that &records group
        type(record_in_t), allocatable :: recs(:)
        logical :: slammer_rounding = .false.
    end type config_t

    !> The check's results.
    type :: suite_res_t
        real(dp), allocatable :: grid(:)            !! check periods (s)
        real(dp), allocatable :: target(:)          !! target elastic 5 % spectrum there (g)
        real(dp) :: target_pga = 0.0_dp             !! the target at T = 0 (g)
        real(dp), allocatable :: psa(:, :)          !! (period, record) 5 % PSA (g)
        real(dp), allocatable :: pga(:)             !! per record (g)
        real(dp), allocatable :: own_scale(:)       !! per record
        real(dp), allocatable :: mean(:)            !! mean PSA of the records read (g)
        real(dp), allocatable :: ratio(:)           !! mean/target (-)
        real(dp), allocatable :: own_mean(:)        !! mean PSA of the records, own scales (g)
        integer :: i_t1 = 0                         !! index of T1 in grid
        logical :: done = .false.                   !! the check was made
        character(len=:), allocatable :: why        !! why not
        type(suite_check_t) :: check
        type(suite_target_t) :: tgt                 !! the target as the library takes it
    end type suite_res_t

contains

    subroutine set_defaults()
        real(dp) :: nan
        nan = ieee_value(nan, ieee_quiet_nan)
        call records_defaults()
        periods = nan
        period_range = nan
        period_count = 0
        spacing = 'linear'
        codes = ''
        kind = 'both'
        c_ag = nan
        c_zone = ''
        c_annex = ''
        c_importance = 1.0_dp
        c_ground = 'A'
        c_damping = 0.05_dp
        c_q = 1.5_dp
        c_beta = 0.2_dp
        k_zone = ''
        k_alpha = nan
        k_zone_map = '2003'
        k_ground = 'B'
        k_importance = 1.0_dp
        k_class = ''
        k_q = 1.0_dp
        k_theta = 1.0_dp
        k_damping = 0.05_dp
        k_eta_min = 0.0_dp
        k_lower_bound = 0.0_dp
        k_exponent = 2.0_dp / 3.0_dp
        t1 = nan
        target = 'EC8_1'
        n_points = 400
        fit = 'linear'
        min_records = 3
        records_from = ''
    end subroutine set_defaults

    subroutine read_spectra(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        if (len(text) > 0) then
            read(text, nml=spectra, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=spectra, iostat=ios, iomsg=iomsg)
        end if
    end subroutine read_spectra

    subroutine read_ec8(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        real(dp) :: ag, importance, damping, q, beta
        character(len=32) :: zone, national_annex, ground
        namelist /ec8/ ag, zone, national_annex, importance, ground, damping, q, beta
        ag = c_ag
        zone = c_zone
        national_annex = c_annex
        importance = c_importance
        ground = c_ground
        damping = c_damping
        q = c_q
        beta = c_beta
        if (len(text) > 0) then
            read(text, nml=ec8, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=ec8, iostat=ios, iomsg=iomsg)
        end if
        if (ios /= 0) return
        c_ag = ag
        c_zone = zone
        c_annex = national_annex
        c_importance = importance
        c_ground = ground
        c_damping = damping
        c_q = q
        c_beta = beta
    end subroutine read_ec8

    subroutine read_eak(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        real(dp) :: alpha, importance, q, theta, damping, eta_min, lower_bound, &
                    elastic_exponent
        character(len=32) :: zone, zone_map, ground, importance_class
        namelist /eak/ zone, alpha, zone_map, ground, importance, importance_class, q, theta, &
            damping, eta_min, lower_bound, elastic_exponent
        zone = k_zone
        alpha = k_alpha
        zone_map = k_zone_map
        ground = k_ground
        importance = k_importance
        importance_class = k_class
        q = k_q
        theta = k_theta
        damping = k_damping
        eta_min = k_eta_min
        lower_bound = k_lower_bound
        elastic_exponent = k_exponent
        if (len(text) > 0) then
            read(text, nml=eak, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=eak, iostat=ios, iomsg=iomsg)
        end if
        if (ios /= 0) return
        k_zone = zone
        k_alpha = alpha
        k_zone_map = zone_map
        k_ground = ground
        k_importance = importance
        k_class = importance_class
        k_q = q
        k_theta = theta
        k_damping = damping
        k_eta_min = eta_min
        k_lower_bound = lower_bound
        k_exponent = elastic_exponent
    end subroutine read_eak

    subroutine read_suite(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        if (len(text) > 0) then
            read(text, nml=suite, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=suite, iostat=ios, iomsg=iomsg)
        end if
    end subroutine read_suite

    !> Read and check the groups, compute every table, write them; print where they
    !> went. stat: 0, ROWS_FAILED (tables written, errmsg says which records failed or
    !> why no check was made), or > 0 for an input or output error (nothing written).
    subroutine run_spectra(path, groups, prefix, stat, errmsg)
        character(len=*), intent(in) :: path              !! input file (for messages)
        type(nml_group), intent(in) :: groups(:)          !! scanned groups
        character(len=*), intent(in) :: prefix            !! output prefix
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        type(nml_group) :: gs, gc, gk, gu, gr
        type(config_t) :: cfg
        type(record_out_t), allocatable :: outs(:)
        type(suite_res_t) :: res
        real(dp), allocatable :: table(:, :)
        character(len=4096), allocatable :: table_notes(:), suite_notes(:)
        integer :: nfailed

        call check_input(path, groups, prefix, gs, gc, gk, gu, gr, cfg, stat, errmsg)
        if (stat /= 0) return
        stat = 1

        ! --- the code spectra (every one is computed before anything is written; a
        ! library refusal is an input error placed at the code's group)
        if (cfg%table) then
            call spectra_table(path, gc, gk, cfg, table, errmsg)
            if (len(errmsg) > 0) return
        end if
        if (cfg%suite) then
            call suite_target(path, gc, gk, cfg, res, errmsg)
            if (len(errmsg) > 0) return
        end if

        ! --- echo the effective input
        if (cfg%table) call echo_spectra(cfg)
        if (find_group(groups, 'ec8') > 0) call echo_ec8(cfg%ec8)
        if (find_group(groups, 'eak') > 0) call echo_eak(cfg%eak)
        if (cfg%suite) then
            call echo_suite(cfg)
            if (len(cfg%records_from) == 0) call echo_records(cfg%recs, cfg%slammer_rounding)
        end if

        call range_notes(path, gs, gu, cfg, table_notes, suite_notes)

        ! --- the records (read, then joined) and the check
        nfailed = 0
        if (cfg%suite) then
            call compute_suite(cfg, outs, res)
            nfailed = count(.not. outs%ok)
            call duration_note(path, gu, cfg, outs, suite_notes)
        end if

        ! --- write
        call write_all(path, prefix, cfg, table, outs, res, table_notes, suite_notes, stat, &
                       errmsg)
        if (stat /= 0) return
        if (cfg%suite) then
            if (nfailed > 0) then
                stat = ROWS_FAILED
                errmsg = int_str(nfailed)//' of '//int_str(size(outs))//' records failed (' &
                         //failed_records(outs, .not. outs%ok)//'): their rows hold NaN and ' &
                         //'status failed; the check fails (the suite checked is not the one ' &
                         //'listed)'
                if (.not. res%done) errmsg = errmsg//'; '//res%why
            else if (.not. res%done) then
                ! a safety net: every refusal of the check is caught as an input error
                stat = ROWS_FAILED
                errmsg = 'no check: '//res%why
            end if
        end if
    end subroutine run_spectra

    !> Read the groups and check them, and the rules across groups and the output names:
    !> stat 1 with errmsg on an input error (before any record is read).
    subroutine check_input(path, groups, prefix, gs, gc, gk, gu, gr, cfg, stat, errmsg)
        character(len=*), intent(in) :: path, prefix
        type(nml_group), intent(in) :: groups(:)
        type(nml_group), intent(out) :: gs, gc, gk, gu, gr
        type(config_t), intent(inout) :: cfg
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg

        call set_defaults()
        call read_optional(path, groups, 'spectra', spectra_keys, read_spectra, gs, stat, &
                           errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'ec8', ec8_keys, read_ec8, gc, stat, errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'eak', eak_keys, read_eak, gk, stat, errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'suite', suite_keys, read_suite, gu, stat, errmsg)
        if (stat /= 0) return
        call read_optional(path, groups, 'records', records_keys, read_records, gr, stat, &
                           errmsg)
        if (stat /= 0) return
        stat = 1
        cfg%table = find_group(groups, 'spectra') > 0
        cfg%suite = find_group(groups, 'suite') > 0
        if (.not. (cfg%table .or. cfg%suite)) then
            errmsg = missing_group(path, 'spectra')//' (it gives the periods and the codes ' &
                     //'of the spectra; or &suite with &records for the check of a suite ' &
                     //'of records)'
            return
        end if
        if (find_group(groups, 'records') > 0 .and. .not. cfg%suite) then
            errmsg = located(path, gr)//'only with &suite (the check of the records ' &
                     //'against a code spectrum: give &suite t1 = ...)'
            return
        end if

        call check_spectra(path, gs, cfg, errmsg)
        if (len(errmsg) > 0) return
        if (cfg%suite) then
            call check_suite(path, gu, gr, cfg, errmsg)
            if (len(errmsg) > 0) return
        end if
        cfg%use_ec8 = any(cfg%codes == CODE_EC8_1 .or. cfg%codes == CODE_EC8_2)
        cfg%use_eak = any(cfg%codes == CODE_EAK)
        if (cfg%suite) then
            cfg%use_ec8 = cfg%use_ec8 .or. cfg%target /= CODE_EAK
            cfg%use_eak = cfg%use_eak .or. cfg%target == CODE_EAK
        end if
        if (cfg%use_ec8) then
            if (find_group(groups, 'ec8') == 0) then
                errmsg = missing_group(path, 'ec8')//' (the EN 1998-1 spectra need it: ag = ' &
                         //'the design ground acceleration (g), or zone = ''Z1''..''Z3'', ' &
                         //'and ground)'
                return
            end if
            call check_ec8(path, gc, cfg%ec8, errmsg)
            if (len(errmsg) > 0) return
        else if (find_group(groups, 'ec8') > 0) then
            errmsg = located(path, gc)//'not used (codes names no EN 1998-1 spectrum, and ' &
                     //'no &suite target is one)'
            return
        end if
        if (cfg%use_eak) then
            if (find_group(groups, 'eak') == 0) then
                errmsg = missing_group(path, 'eak')//' (the EAK 2000 spectra need it: zone ' &
                         //'or alpha, ground, ...)'
                return
            end if
            call check_eak(path, gk, cfg%eak, errmsg)
            if (len(errmsg) > 0) return
        else if (find_group(groups, 'eak') > 0) then
            errmsg = located(path, gk)//'not used (codes names no EAK spectrum, and the ' &
                     //'&suite target is not EAK)'
            return
        end if
        call check_table_names(path, prefix, cfg, errmsg)
        if (len(errmsg) > 0) return
        stat = 0
    end subroutine check_input

    !> Two tables of this run must not have the same file name (the code spectra and the
    !> records' spectra under an output prefix ending in '_suite'): an input error before
    !> any record is read.
    subroutine check_table_names(path, prefix, cfg, errmsg)
        character(len=*), intent(in) :: path, prefix
        type(config_t), intent(in) :: cfg
        character(len=:), allocatable, intent(out) :: errmsg
        logical :: have(size(spectra_tables))
        integer :: i, j
        errmsg = ''
        have = cfg%suite
        have(1) = cfg%table
        do i = 1, size(spectra_tables)
            do j = i + 1, size(spectra_tables)
                if (.not. (have(i) .and. have(j))) cycle
                if (table_path(prefix, spectra_tables(i), 'csv') /= &
                    table_path(prefix, spectra_tables(j), 'csv')) cycle
                errmsg = output_located(path)//'the tables '''//trim(spectra_tables(i)) &
                         //''' and '''//trim(spectra_tables(j))//''' would both be ' &
                         //table_path(prefix, spectra_tables(i), 'csv')//' (&spectra and ' &
                         //'&suite under an output prefix ending in ''_suite''): choose ' &
                         //'another output prefix'
                return
            end do
        end do
    end subroutine check_table_names

    !> Warnings on the periods (stderr and header notes) known before any record is
    !> read: &spectra periods beyond 4 s (EN 1998-1 states the spectra up to 4 s) in
    !> table_notes, the check reaching beyond 4 s in suite_notes.
    subroutine range_notes(path, gs, gu, cfg, table_notes, suite_notes)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gs, gu
        type(config_t), intent(in) :: cfg
        character(len=4096), allocatable, intent(out) :: table_notes(:), suite_notes(:)
        allocate(table_notes(0), suite_notes(0))
        if (cfg%table) then
            if (any(cfg%periods > en_max_period)) call add_warning(located(path, gs), &
                'periods up to '//g6(maxval(cfg%periods))//' s: EN 1998-1 states the ' &
                //'spectra up to '//g6(en_max_period)//' s; beyond, the forms (3.5)/(3.16) ' &
                //'and (K.3) are extended', table_notes)
        end if
        if (cfg%suite .and. 2.0_dp * cfg%t1 > en_max_period) call add_warning( &
            located(path, gu), 't1 = '//g6(cfg%t1)//': the check reaches 2 T1 = ' &
            //g6(2.0_dp * cfg%t1)//' s, beyond the '//g6(en_max_period)//' s up to which ' &
            //'EN 1998-1 states the spectrum', suite_notes)
    end subroutine range_notes

    !> A warning (stderr and header note) when 2 T1 exceeds the duration of the longest
    !> record read.
    subroutine duration_note(path, gu, cfg, outs, notes)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gu
        type(config_t), intent(in) :: cfg
        type(record_out_t), intent(in) :: outs(:)
        character(len=4096), allocatable, intent(inout) :: notes(:)
        real(dp) :: longest
        integer :: ir
        if (.not. any(outs%ok)) return
        longest = 0.0_dp
        do ir = 1, size(outs)
            if (outs(ir)%ok) longest = max(longest, (outs(ir)%npts - 1) * outs(ir)%dt)
        end do
        if (2.0_dp * cfg%t1 > longest) call add_warning(located(path, gu), 't1 = ' &
            //g6(cfg%t1)//': 2 T1 = '//g6(2.0_dp * cfg%t1)//' s exceeds the duration of ' &
            //'the longest record read ('//g6(longest)//' s)', notes)
    end subroutine duration_note

    !> "warning: <where><text>" on stderr and "WARNING: <text>" appended to notes.
    subroutine add_warning(where, text, notes)
        character(len=*), intent(in) :: where, text
        character(len=4096), allocatable, intent(inout) :: notes(:)
        write(error_unit, '(a)') 'warning: '//where//text
        notes = [character(len=4096) :: notes, 'WARNING: '//text]
    end subroutine add_warning

    !> Write every table of the run and say where they went (on an error none is left:
    !> stat 1 and errmsg placed at &run output).
    subroutine write_all(path, prefix, cfg, table, outs, res, table_notes, suite_notes, &
                         stat, errmsg)
        character(len=*), intent(in) :: path, prefix
        type(config_t), intent(in) :: cfg
        real(dp), allocatable, intent(in) :: table(:, :)
        type(record_out_t), allocatable, intent(in) :: outs(:)
        type(suite_res_t), intent(in) :: res
        character(len=*), intent(in) :: table_notes(:), suite_notes(:)   !! header notes
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=512) :: files(2, 5)
        character(len=4096), allocatable :: head(:)
        integer :: k

        files = ''
        stat = 0
        if (cfg%table) call write_spectra(path, prefix, cfg, table, table_notes, files(:, 1), &
                                          stat, errmsg)
        if (cfg%suite .and. stat == 0) then
            head = [character(len=4096) :: suite_comments(path, cfg, outs, res), suite_notes]
            call write_summary(prefix, cfg, outs, res, head, files(:, 2), stat, errmsg)
            if (stat == 0) call write_records(prefix, outs, res, head, files(:, 3), stat, &
                                              errmsg)
            if (stat == 0) call write_mean(prefix, res, head, files(:, 4), stat, errmsg)
            if (stat == 0) call write_long(prefix, outs, res, head, files(:, 5), stat, errmsg)
        end if
        if (stat /= 0) then
            do k = 1, size(files, 2)
                if (len_trim(files(1, k)) > 0) call delete_files(files(:, k))
            end do
            stat = 1
            errmsg = output_located(path)//errmsg
            return
        end if
        if (cfg%table) call say_written('code spectra', files(:, 1))
        if (cfg%suite) then
            call say_written('record-suite check', files(:, 2))
            call say_written('suite records', files(:, 3))
            call say_written('suite mean spectrum', files(:, 4))
            call say_written('suite spectra', files(:, 5))
        end if
    end subroutine write_all

    ! ------------------------------------------------------------------------------
    ! Checks
    ! ------------------------------------------------------------------------------

    !> &spectra: the periods, the codes and the kind (defaults without the group: no
    !> table; codes and kind then unused).
    subroutine check_spectra(path, gs, cfg, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gs
        type(config_t), intent(inout) :: cfg
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: where
        integer :: i, j, n, code

        where = located(path, gs)
        errmsg = ''
        allocate(cfg%codes(0))
        if (.not. cfg%table) then
            allocate(cfg%periods(0))
            cfg%grid = ''
            return
        end if
        call axis_values(gs, 'periods', 'period', periods, period_range, period_count, &
                         spacing, .false., .false., max_periods, cfg%periods, cfg%grid, &
                         errmsg, required=.true.)
        if (len(errmsg) > 0) then
            errmsg = where//errmsg
            return
        end if
        if (given(gs, 'codes')) then
            call count_strings(codes, 'codes', n, errmsg)
            if (len(errmsg) > 0) then
                errmsg = where//errmsg//' (give some of '//upper_list(code_names)//')'
                return
            end if
            do i = 1, n
                code = name_index(codes(i), code_names)
                if (code == 0) then
                    errmsg = where//list_item('codes', i)//' = '''//trim(codes(i)) &
                             //''': unknown code (allowed: '//upper_list(code_names)//')'
                    return
                end if
                do j = 1, size(cfg%codes)
                    if (cfg%codes(j) == code) then
                        errmsg = where//list_item('codes', i)//' = '''//trim(codes(i)) &
                                 //''': given twice'
                        return
                    end if
                end do
                cfg%codes = [cfg%codes, code]
            end do
        else
            cfg%codes = [CODE_EC8_1, CODE_EC8_2, CODE_EAK]
        end if
        cfg%kind = name_index(kind, kind_names)
        if (cfg%kind == 0) then
            errmsg = where//'kind = '''//trim(kind)//''': unknown kind (allowed: ' &
                     //join(kind_names)//')'
            return
        end if
    end subroutine check_spectra

    !> &ec8: ag or a zone of the Greek NA, the ground, damping, q, beta.
    subroutine check_ec8(path, gc, p, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gc
        type(ec8_t), intent(inout) :: p
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: where
        character(len=512) :: msg
        real(dp) :: ag, v(1)
        integer :: st

        where = located(path, gc)
        errmsg = ''
        if (given(gc, 'zone')) then
            p%zone = name_index(c_zone, ec8_zones)
            if (p%zone == 0) then
                errmsg = where//'zone = '''//trim(c_zone)//''': unknown zone (allowed: Z1, ' &
                         //'Z2, Z3 of the Greek National Annex)'
                return
            end if
        end if
        if (given(gc, 'national_annex')) then
            if (name_index(c_annex, annex_names) == 0) then
                errmsg = where//'national_annex = '''//trim(c_annex)//''': unknown ' &
                         //'national annex (allowed: GR, the only one with zones here)'
                return
            end if
        end if
        ! the library's rule, as Python's (ec8_design_ag): one of ag and zone; with ag,
        ! importance stays 1 and national_annex is only checked
        ag = ieee_value(1.0_dp, ieee_quiet_nan)
        if (given(gc, 'ag')) ag = c_ag
        msg = ''
        call ec8_design_ag(ag, EC8_ANNEX_GR, p%zone, c_importance, p%ag, st, msg)
        if (st /= SEISPULSE_SUCCESS) then
            errmsg = where//trim(msg)
            return
        end if
        p%importance = c_importance
        if (p%zone /= 0) call ec8_reference_pga(EC8_ANNEX_GR, p%zone, p%agr, st)
        p%ground = name_index(c_ground, ec8_grounds)
        if (p%ground == 0) then
            errmsg = where//'ground = '''//trim(c_ground)//''': unknown ground type ' &
                     //'(allowed: A, B, C, D, E of EN 1998-1 Table 3.1)'
            return
        end if
        if (.not. in_range(where, 'damping', c_damping, 0.0_dp, 1.0_dp, .false., errmsg, &
            damping_rule, open_hi=.true.)) return
        p%damping = c_damping
        ! q and beta: the library's checks (the design spectrum at T = 0)
        msg = ''
        call ec8_design_spectrum([0.0_dp], p%ag, EC8_SPECTRUM_TYPE_1, p%ground, c_q, c_beta, &
                                 v, st, msg)
        if (st /= SEISPULSE_SUCCESS) then
            errmsg = where//trim(msg)
            return
        end if
        p%q = c_q
        p%beta = c_beta
    end subroutine check_ec8

    !> &eak: zone (of zone_map) or alpha, ground, importance or its class, q, theta,
    !> damping, and the unverified parameters.
    subroutine check_eak(path, gk, p, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gk
        type(eak_t), intent(inout) :: p
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: where
        character(len=512) :: msg
        real(dp) :: t_1, t_2, v(1)
        integer :: st, code

        where = located(path, gk)
        errmsg = ''
        code = name_index(k_zone_map, map_names)
        if (code == 0) then
            errmsg = where//'zone_map = '''//trim(k_zone_map)//''': unknown zone map ' &
                     //'(allowed: 2003, 2000)'
            return
        end if
        p%zone_map = merge(EAK_MAP_2003, EAK_MAP_2000, code == 1)
        if (given(gk, 'zone') .and. given(gk, 'alpha')) then
            errmsg = where//'zone, alpha: give only one of them (zone: a seismic zone; ' &
                     //'alpha: A/g directly)'
            return
        end if
        if (given(gk, 'alpha')) then
            if (given(gk, 'zone_map')) then
                errmsg = where//'zone_map: only with zone (alpha is given directly)'
                return
            end if
            p%alpha = k_alpha
        else
            ! as Python: the default zone Z2 is a zone of the 2003 map only
            if (.not. given(gk, 'zone') .and. p%zone_map == EAK_MAP_2000) then
                errmsg = where//'zone: missing (the default Z2 is a zone of the 2003 map; ' &
                         //'with zone_map = ''2000'' give zone = ''I''..''IV'')'
                return
            end if
            if (.not. given(gk, 'zone')) k_zone = 'Z2'
            if (p%zone_map == EAK_MAP_2003) then
                p%zone = name_index(k_zone, ec8_zones)
                if (p%zone == 0) then
                    errmsg = where//'zone = '''//trim(k_zone)//''': unknown zone of the 2003 ' &
                             //'map (allowed: Z1, Z2, Z3; or zone_map = ''2000'' with I, II, ' &
                             //'III, IV)'
                    return
                end if
            else
                p%zone = name_index(k_zone, eak_zones_2000)
                if (p%zone == 0) then
                    errmsg = where//'zone = '''//trim(k_zone)//''': unknown zone of the 2000 ' &
                             //'map (allowed: I, II, III, IV)'
                    return
                end if
            end if
            msg = ''
            call eak2000_zone_acceleration(p%zone, p%zone_map, p%alpha, st, msg)
            if (st /= SEISPULSE_SUCCESS) then
                errmsg = where//'zone = '''//trim(k_zone)//''': '//reason(msg)
                return
            end if
        end if
        p%ground = name_index(k_ground, eak_grounds)
        if (p%ground == 0) then
            errmsg = where//'ground = '''//trim(k_ground)//''': unknown ground category ' &
                     //'(allowed: A, B, C, D)'
            return
        end if
        p%ground = EAK_GROUND_A + p%ground - 1
        msg = ''
        call eak2000_ground_parameters(p%ground, t_1, t_2, st, msg)
        if (st /= SEISPULSE_SUCCESS) then
            errmsg = where//'ground = '''//trim(k_ground)//''': '//reason(msg)
            return
        end if
        if (given(gk, 'importance') .and. given(gk, 'importance_class')) then
            errmsg = where//'importance, importance_class: give only one of them (a factor ' &
                     //'gamma_I, or a class I..IV)'
            return
        end if
        if (given(gk, 'importance_class')) then
            p%importance_class = name_index(k_class, class_names)
            if (p%importance_class == 0) then
                errmsg = where//'importance_class = '''//trim(k_class)//''': unknown ' &
                         //'importance class (allowed: I, II, III, IV)'
                return
            end if
            msg = ''
            call eak2000_importance_factor(p%importance_class, p%importance, st, msg)
            if (st /= SEISPULSE_SUCCESS) then
                errmsg = where//'importance_class = '''//trim(k_class)//''': '//reason(msg)
                return
            end if
        else
            p%importance = k_importance
        end if
        if (.not. in_range(where, 'damping', k_damping, 0.0_dp, 1.0_dp, .false., errmsg, &
            damping_rule, open_hi=.true.)) return
        p%damping = k_damping
        ! alpha, importance, q, theta, lower_bound, eta_min and the exponent: the library's
        ! checks (both spectra at T = 0), placed at &eak
        msg = ''
        call eak2000_design_spectrum([0.0_dp], p%alpha, p%ground, p%importance, k_q, k_theta, &
                                     100.0_dp*k_damping, k_eta_min, k_lower_bound, v, st, msg)
        if (st == SEISPULSE_SUCCESS) call eak2000_elastic_spectrum([0.0_dp], p%alpha, &
            p%ground, p%importance, 100.0_dp*k_damping, k_eta_min, k_exponent, v, st, msg)
        if (st /= SEISPULSE_SUCCESS) then
            ! the library's argument `exponent` is the key elastic_exponent here
            errmsg = where//trim(msg)
            if (index(msg, 'exponent = ') == 1) errmsg = where//'elastic_'//trim(msg)
            return
        end if
        p%q = k_q
        p%theta = k_theta
        p%eta_min = k_eta_min
        p%lower_bound = k_lower_bound
        p%exponent = k_exponent
    end subroutine check_eak

    !> &suite and the records (&records here, or that of records_from).
    subroutine check_suite(path, gu, gr, cfg, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gu, gr
        type(config_t), intent(inout) :: cfg
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=:), allocatable :: where, msg
        type(nml_group), allocatable :: other(:)
        integer :: st, ig

        where = located(path, gu)
        errmsg = ''
        if (.not. given(gu, 't1')) then
            errmsg = where//'t1: missing (the fundamental period T1 of the structure, s: ' &
                     //'the check covers 0.2 T1 .. 2 T1)'
            return
        end if
        if (.not. in_range(where, 't1', t1, 0.0_dp, big, .true., errmsg, &
            'must be a finite period > 0 (s)')) return
        cfg%t1 = t1
        cfg%target = name_index(target, code_names)
        if (cfg%target == 0) then
            errmsg = where//'target = '''//trim(target)//''': unknown target (allowed: ' &
                     //upper_list(code_names)//', each code''s elastic spectrum)'
            return
        end if
        ! no upper limit (as Python's): the grid is allocated
        if (n_points < 2) then
            errmsg = where//'n_points = '//int_str(n_points)//': must be >= 2 ' &
                     //'(log-spaced periods of the check)'
            return
        end if
        cfg%n_points = n_points
        cfg%fit = name_index(fit, fit_names)
        if (cfg%fit == 0) then
            errmsg = where//'fit = '''//trim(fit)//''': unknown fit (allowed: ' &
                     //join(fit_names)//')'
            return
        end if
        cfg%fit = merge(SUITE_FIT_LINEAR, SUITE_FIT_LOG, cfg%fit == 1)
        if (min_records < 1) then
            errmsg = where//'min_records = '//int_str(min_records)//': must be >= 1 ' &
                     //'(EN 1998-1 3.2.3.1.2(4): at least 3)'
            return
        end if
        cfg%min_records = min_records

        ! --- the records: here, or in the input named by records_from
        cfg%records_from = ''
        if (given(gu, 'records_from')) then
            if (len_trim(records_from) == 0) then
                errmsg = where//'records_from: empty (give the input file whose &records ' &
                         //'to use, relative to this file)'
                return
            end if
            if (gr%line > 0) then
                errmsg = located(path, gr)//'not with &suite records_from (the records come ' &
                         //'from '''//trim(records_from)//'''; give one of them)'
                return
            end if
            cfg%records_from = resolve(path, trim(adjustl(records_from)))
            call scan_file(cfg%records_from, other, st, msg)
            if (st /= 0) then
                errmsg = where//'records_from = '''//trim(records_from)//''': '//msg
                return
            end if
            ig = find_group(other, 'records')
            if (ig == 0) then
                errmsg = where//'records_from = '''//trim(records_from)//''': it has no ' &
                         //'&records group'
                return
            end if
            cfg%gr = other(ig)
            cfg%rec_path = cfg%records_from
            call check_keys(cfg%rec_path, cfg%gr, records_keys, st, msg)
            if (st == 0) call read_group(cfg%rec_path, cfg%gr, read_records, st, msg)
            if (st /= 0) then
                errmsg = msg
                return
            end if
        else
            if (gr%line == 0) then
                errmsg = missing_group(path, 'records')//records_missing(:len(records_missing) &
                         - 1)//'; or &suite records_from = ''other.nml'')'
                return
            end if
            cfg%gr = gr
            cfg%rec_path = path
        end if
        call check_records(cfg%rec_path, cfg%gr, cfg%recs, cfg%slammer_rounding, errmsg)
        if (len(errmsg) > 0) return
        if (size(cfg%recs) < cfg%min_records) then
            errmsg = located(cfg%rec_path, cfg%gr)//'files: '//int_str(size(cfg%recs)) &
                     //' records, fewer than &suite min_records = '//int_str(cfg%min_records) &
                     //' (EN 1998-1 3.2.3.1.2(4): at least 3)'
            return
        end if
    end subroutine check_suite

    ! ------------------------------------------------------------------------------
    ! The code spectra
    ! ------------------------------------------------------------------------------

    !> Spectrum of `code` at `periods` (g): elastic (with `damping`, a ratio) or design.
    !> stat /= 0 with the library's message.
    subroutine code_spectrum(cfg, code, elastic, damping, periods, values, stat, msg)
        type(config_t), intent(in) :: cfg
        integer, intent(in) :: code
        logical, intent(in) :: elastic
        real(dp), intent(in) :: damping
        real(dp), intent(in) :: periods(:)
        real(dp), intent(out) :: values(:)
        integer, intent(out) :: stat
        character(len=*), intent(inout) :: msg
        integer :: stype
        if (code == CODE_EAK) then
            associate (p => cfg%eak)
                if (elastic) then
                    call eak2000_elastic_spectrum(periods, p%alpha, p%ground, p%importance, &
                        100.0_dp * damping, p%eta_min, p%exponent, values, stat, msg)
                else
                    call eak2000_design_spectrum(periods, p%alpha, p%ground, p%importance, &
                        p%q, p%theta, 100.0_dp * damping, p%eta_min, p%lower_bound, values, &
                        stat, msg)
                end if
            end associate
        else
            stype = ec8_type(code)
            associate (p => cfg%ec8)
                if (elastic) then
                    call ec8_elastic_spectrum(periods, p%ag, stype, p%ground, &
                        100.0_dp * damping, values, stat, msg)
                else
                    call ec8_design_spectrum(periods, p%ag, stype, p%ground, p%q, p%beta, &
                        values, stat, msg)
                end if
            end associate
        end if
    end subroutine code_spectrum

    !> The spectra table: period, then one column per code and kind.
    subroutine spectra_table(path, gc, gk, cfg, table, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gc, gk
        type(config_t), intent(in) :: cfg
        real(dp), allocatable, intent(out) :: table(:, :)
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=512) :: msg
        integer :: i, j, col, st
        logical :: elastic

        errmsg = ''
        allocate(table(size(cfg%periods), 1 + size(cfg%codes) * merge(2, 1, cfg%kind == 3)))
        table(:, 1) = cfg%periods
        col = 1
        do i = 1, size(cfg%codes)
            do j = 1, 2
                if (cfg%kind /= 3 .and. cfg%kind /= j) cycle
                elastic = j == 1
                col = col + 1
                msg = ''
                if (cfg%codes(i) == CODE_EAK) then
                    call code_spectrum(cfg, cfg%codes(i), elastic, cfg%eak%damping, &
                                       cfg%periods, table(:, col), st, msg)
                    if (st /= SEISPULSE_SUCCESS) errmsg = located(path, gk)//trim(msg)
                else
                    call code_spectrum(cfg, cfg%codes(i), elastic, cfg%ec8%damping, &
                                       cfg%periods, table(:, col), st, msg)
                    if (st /= SEISPULSE_SUCCESS) errmsg = located(path, gc)//trim(msg)
                end if
                if (st /= SEISPULSE_SUCCESS) return
            end do
        end do
    end subroutine spectra_table

    !> The target of the check (the library's suite_target_t) and its value at T = 0,
    !> checked before any record is read (a refusal is placed at &ec8 or &eak).
    subroutine suite_target(path, gc, gk, cfg, res, errmsg)
        character(len=*), intent(in) :: path
        type(nml_group), intent(in) :: gc, gk
        type(config_t), intent(in) :: cfg
        type(suite_res_t), intent(out) :: res
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=512) :: msg
        integer :: st

        errmsg = ''
        msg = ''
        if (cfg%target == CODE_EAK) then
            res%tgt = suite_target_t(code=SUITE_TARGET_EAK, alpha=cfg%eak%alpha, &
                                     ground=cfg%eak%ground, importance=cfg%eak%importance, &
                                     eta_min=cfg%eak%eta_min, exponent=cfg%eak%exponent)
        else
            res%tgt = suite_target_t(code=SUITE_TARGET_EC8, spectrum_type=ec8_type(cfg%target), &
                                     ag=cfg%ec8%ag, &
                                     ground=cfg%ec8%ground)
        end if
        call suite_target_pga(res%tgt, res%target_pga, st, msg)
        if (st /= SEISPULSE_SUCCESS) then
            if (cfg%target == CODE_EAK) then
                errmsg = located(path, gk)//trim(msg)
            else
                errmsg = located(path, gc)//trim(msg)
            end if
        end if
    end subroutine suite_target

    !> Without a check: the check grid (suite_records_grid, as ec8_suite_check_records)
    !> and the target there, for the tables of NaN.
    subroutine plain_grid(cfg, res)
        type(config_t), intent(in) :: cfg
        type(suite_res_t), intent(inout) :: res
        real(dp) :: grid(suite_records_room(cfg%n_points, 0))
        integer :: n, st
        call suite_records_grid(res%tgt, cfg%t1, cfg%n_points, [real(dp) ::], grid, n, st)
        res%grid = grid(1:n)
        allocate(res%target(n))
        call suite_target_values(res%tgt, res%grid, res%target, st)
    end subroutine plain_grid

    ! ------------------------------------------------------------------------------
    ! The records and the check
    ! ------------------------------------------------------------------------------

    !> Every record (read, polarity, scale), then the check on the records read
    !> (ec8_suite_check_records: the grid, each record's 5 % PSA with exact peaks, the rules
    !> with the least ratios refined between grid periods). A record that fails to read, or
    !> that the check refuses (bad_record: zero PGA or PSA), keeps o%ok = .false. and its
    !> message (reported on stderr at once); the check is then made on the others.
    subroutine compute_suite(cfg, outs, res)
        type(config_t), intent(in) :: cfg
        type(record_out_t), allocatable, intent(out) :: outs(:)
        type(suite_res_t), intent(inout) :: res
        real(dp), allocatable :: accel(:), joined(:), dts(:), per(:), psa(:, :), tv(:), &
                                 m(:), rt(:), om(:), own(:), pga(:)
        integer, allocatable :: first(:), npts(:), idx(:)
        character(len=:), allocatable :: where
        character(len=4096) :: msg
        integer :: nrec, ir, st, nok, room, n, bad

        where = located(cfg%rec_path, cfg%gr)
        nrec = size(cfg%recs)
        allocate(outs(nrec), first(nrec), npts(nrec), dts(nrec), joined(0))
        first = 1
        npts = 1
        dts = 1.0_dp
        do ir = 1, nrec
            associate (r => cfg%recs(ir), o => outs(ir))
                call load_record(where, r, ir, nrec, 'spectra', cfg%slammer_rounding, o, accel)
                if (.not. o%ok) cycle
                first(ir) = size(joined) + 1
                npts(ir) = size(accel)
                dts(ir) = o%dt
                joined = [joined, accel]
            end associate
        end do

        ! --- the check on the records read (again without a record the check refuses)
        res%done = .false.
        room = suite_records_room(cfg%n_points, 0)
        do
            nok = count(outs%ok)
            if (nok < cfg%min_records) then
                res%why = 'the check needs at least min_records = '//int_str(cfg%min_records) &
                          //' records and only '//int_str(nok)//' were read: the summary ' &
                          //'holds NaN'
                exit
            end if
            idx = pack([(ir, ir = 1, nrec)], outs%ok)
            if (allocated(psa)) deallocate(per, psa, tv, m, rt, om, own, pga)
            allocate(per(room), psa(room, nok), tv(room), m(room), rt(room), om(room), &
                     own(nok), pga(nok))
            msg = ''
            call ec8_suite_check_records(joined, first(idx), npts(idx), dts(idx), res%tgt, &
                                         cfg%t1, cfg%fit, res%check, per, n, psa, pga, tv, m, &
                                         rt, om, own, st, msg, n_points=cfg%n_points, &
                                         min_records=cfg%min_records, bad_record=bad)
            if (st == SEISPULSE_SUCCESS) then
                res%done = .true.
                exit
            end if
            if (bad == 0) then
                res%why = 'the check failed: '//trim(msg)
                exit
            end if
            associate (o => outs(idx(bad)))
                o%ok = .false.
                o%message = reason(msg)
                call report(where//record_place(idx(bad), cfg%recs(idx(bad)))//': ' &
                            //o%message)
            end associate
        end do

        if (.not. res%done) then
            call plain_grid(cfg, res)
            n = size(res%grid)
        else
            res%grid = per(1:n)
            res%target = tv(1:n)
        end if
        allocate(res%psa(n, nrec), res%pga(nrec), res%own_scale(nrec), res%mean(n), &
                 res%ratio(n), res%own_mean(n))
        res%psa = ieee_value(1.0_dp, ieee_quiet_nan)
        res%pga = ieee_value(1.0_dp, ieee_quiet_nan)
        res%own_scale = ieee_value(1.0_dp, ieee_quiet_nan)
        res%mean = ieee_value(1.0_dp, ieee_quiet_nan)
        res%ratio = res%mean
        res%own_mean = res%mean
        ! T1 is on the grid (an extra period): the one closest to it
        res%i_t1 = minloc(abs(res%grid - cfg%t1), 1)
        if (.not. res%done) return
        res%psa(:, idx) = psa(1:n, :)
        res%pga(idx) = pga
        res%own_scale(idx) = own
        res%mean = m(1:n)
        res%ratio = rt(1:n)
        res%own_mean = om(1:n)
    end subroutine compute_suite

    ! ------------------------------------------------------------------------------
    ! Echo
    ! ------------------------------------------------------------------------------

    !> &spectra with the values in use; the periods as a list.
    subroutine echo_spectra(cfg)
        type(config_t), intent(in) :: cfg
        real(dp) :: periods(size(cfg%periods))
        character(len=5) :: codes(size(cfg%codes))
        character(len=7) :: kind
        integer :: i
        namelist /spectra/ periods, codes, kind
        periods = cfg%periods
        do i = 1, size(cfg%codes)
            codes(i) = trim(upper(code_names(cfg%codes(i))))
        end do
        kind = kind_names(cfg%kind)
        write(echo_unit(), nml=spectra)
    end subroutine echo_spectra

    !> &ec8 with the values in use (only the keys the input gave are kept).
    subroutine echo_ec8(p)
        type(ec8_t), intent(in) :: p
        real(dp) :: ag, importance, damping, q, beta
        character(len=2) :: zone, national_annex
        character(len=1) :: ground
        namelist /ec8/ ag, zone, national_annex, importance, ground, damping, q, beta
        ag = p%ag
        zone = ''
        if (p%zone > 0) zone = trim(upper(ec8_zones(p%zone)))
        national_annex = 'GR'
        importance = p%importance
        ground = trim(upper(ec8_grounds(p%ground)))
        damping = p%damping
        q = p%q
        beta = p%beta
        write(echo_unit(), nml=ec8)
    end subroutine echo_ec8

    !> &eak with the values in use (only the keys the input gave are kept).
    subroutine echo_eak(p)
        type(eak_t), intent(in) :: p
        real(dp) :: alpha, importance, q, theta, damping, eta_min, lower_bound, &
                    elastic_exponent
        character(len=3) :: zone, importance_class
        character(len=4) :: zone_map
        character(len=1) :: ground
        namelist /eak/ zone, alpha, zone_map, ground, importance, importance_class, q, theta, &
            damping, eta_min, lower_bound, elastic_exponent
        zone = ''
        if (p%zone > 0) zone = trim(zone_name(p))
        alpha = p%alpha
        zone_map = map_names(merge(1, 2, p%zone_map == EAK_MAP_2003))
        ground = trim(upper(eak_grounds(p%ground - EAK_GROUND_A + 1)))
        importance = p%importance
        importance_class = ''
        if (p%importance_class > 0) importance_class = trim(upper(class_names(p%importance_class)))
        q = p%q
        theta = p%theta
        damping = p%damping
        eta_min = p%eta_min
        lower_bound = p%lower_bound
        elastic_exponent = p%exponent
        write(echo_unit(), nml=eak)
    end subroutine echo_eak

    !> &suite with the values in use; records_from relative to the echo file.
    subroutine echo_suite(cfg)
        type(config_t), intent(in) :: cfg
        call echo_n(max(1, len(echo_path(cfg%records_from))))
    contains
        subroutine echo_n(flen)
            integer, intent(in) :: flen
            real(dp) :: t1
            integer :: n_points, min_records
            character(len=5) :: target
            character(len=6) :: fit
            character(len=flen) :: records_from
            namelist /suite/ t1, target, n_points, fit, min_records, records_from
            t1 = cfg%t1
            target = trim(upper(code_names(cfg%target)))
            n_points = cfg%n_points
            fit = fit_names(merge(1, 2, cfg%fit == SUITE_FIT_LINEAR))
            min_records = cfg%min_records
            records_from = echo_path(cfg%records_from)
            write(echo_unit(), nml=suite)
        end subroutine echo_n
    end subroutine echo_suite

    ! ------------------------------------------------------------------------------
    ! Output
    ! ------------------------------------------------------------------------------

    !> The header lines that give the parameters of the codes in use (numbers to 6
    !> significant digits; the echo file has them in full).
    function code_lines(cfg) result(lines)
        type(config_t), intent(in) :: cfg
        character(len=4096), allocatable :: lines(:)
        character(len=:), allocatable :: s
        real(dp) :: sf, tb, tc, td, t_1, t_2
        character(len=512) :: msg
        integer :: st, k
        logical :: used(3), design
        ! the codes of the table and the target; design spectra only in the table
        do k = 1, 3
            used(k) = any(cfg%codes == k) .or. (cfg%suite .and. cfg%target == k)
        end do
        design = cfg%table .and. cfg%kind /= 1
        allocate(lines(0))
        if (cfg%use_ec8) then
            associate (p => cfg%ec8)
                if (p%zone > 0) then
                    s = 'EN 1998-1: ag = gamma_I a_gR = '//g6(p%importance)//' x ' &
                        //g6(p%agr)//' = '//g6(p%ag)//' g (zone ' &
                        //trim(upper(ec8_zones(p%zone)))//' of the Greek National Annex, ' &
                        //'the 2003 map [PRDA24], doc/codes.md section 1; every other NDP ' &
                        //'the recommended value: the Greek NA''s other NDPs were not ' &
                        //'verified here)'
                else
                    s = 'EN 1998-1: ag = '//g6(p%ag)//' g (given; recommended NDPs)'
                end if
                s = s//'; ground '//trim(upper(ec8_grounds(p%ground)))
                lines = [character(len=4096) :: lines, s]
                do k = CODE_EC8_1, CODE_EC8_2
                    if (.not. used(k)) cycle
                    msg = ''
                    call ec8_ground_parameters(ec8_type(k), p%ground, sf, tb, tc, td, st, msg)
                    lines = [character(len=4096) :: lines, trim(upper(code_names(k))) &
                        //' (type '//int_str(ec8_type(k))//'): S = '//g6(sf)//', TB = ' &
                        //g6(tb)//' s, TC = '//g6(tc)//' s, TD = '//g6(td) &
                        //' s (EN 1998-1 Table 3.'//int_str(ec8_type(k) + 1)//')']
                end do
                s = 'EN 1998-1 elastic Se (3.2)-(3.5): damping ratio '//g6(p%damping) &
                    //' (eta = '//g6(ec8_damping_correction(100.0_dp * p%damping))//')'
                if (cfg%suite) s = s//'; the target of the check: damping 0.05 (eta = 1)'
                if (design) s = s//'; design Sd (3.13)-(3.16): q = '//g6(p%q) &
                    //', beta = '//g6(p%beta)
                lines = [character(len=4096) :: lines, s]
            end associate
        end if
        if (cfg%use_eak) then
            associate (p => cfg%eak)
                msg = ''
                call eak2000_ground_parameters(p%ground, t_1, t_2, st, msg)
                if (p%zone > 0) then
                    s = 'EAK 2000: A/g = '//g6(p%alpha)//' (zone '//zone_name(p) &
                        //' of the '//map_names(merge(1, 2, p%zone_map == EAK_MAP_2003)) &
                        //' map)'
                else
                    s = 'EAK 2000: A/g = '//g6(p%alpha)//' (given)'
                end if
                s = s//'; ground '//trim(upper(eak_grounds(p%ground - EAK_GROUND_A + 1))) &
                    //' (EAK corner periods T1/T2 = '//g6(t_1)//'/'//g6(t_2) &
                    //' s); gamma_I = '//g6(p%importance)
                if (p%importance_class > 0) s = s//' (class ' &
                    //trim(upper(class_names(p%importance_class)))//')'
                s = s//'; beta0 = '//g6(EAK_BETA0)//'; elastic Phi_e: damping ratio ' &
                    //g6(p%damping)//' (eta = '//g6( &
                    eak2000_damping_correction(100.0_dp * p%damping, p%eta_min))//'), ' &
                    //'long-period exponent '//exponent_text(p%exponent)
                if (cfg%suite .and. cfg%target == CODE_EAK) s = s//'; the target of the ' &
                    //'check: Phi_e at damping 0.05 (eta = 1)'
                if (design) s = s//'; design Phi_d (K.1)-(K.3): q = '//g6(p%q) &
                    //', theta = '//g6(p%theta)//', eta as Phi_e'
                lines = [character(len=4096) :: lines, s]
                lines = [character(len=4096) :: lines, 'EAK 2000 values from secondary ' &
                    //'sources; unverified: the rules for theta (here ' &
                    //g6(p%theta)//'), eta_min = '//g6(p%eta_min) &
                    //' (0: no floor on eta), lower_bound = '//g6(p%lower_bound) &
                    //' (Phi_d >= lower_bound gamma_I A; 0: none, 0.25 is a recollection), ' &
                    //'the elastic long-period exponent '//exponent_text(p%exponent) &
                    //' (2/3 as Phi_d; 1 in one implementation), ground X (refused); ' &
                    //'doc/eak2000.md']
            end associate
        end if
    end function code_lines

    !> The code spectra table: its column names built next to the values' order of
    !> spectra_table (code by code, elastic then design).
    subroutine write_spectra(path, prefix, cfg, table, notes, files_out, stat, errmsg)
        character(len=*), intent(in) :: path, prefix
        type(config_t), intent(in) :: cfg
        real(dp), intent(in) :: table(:, :)
        character(len=*), intent(in) :: notes(:)
        character(len=*), intent(out) :: files_out(2)
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=4096), allocatable :: comments(:)
        character(len=16), allocatable :: col_units(:)

        allocate(col_units(size(table, 2)))
        col_units = 'g'
        col_units(1) = 's'
        comments = [character(len=4096) :: 'seispulse analysis spectra: code spectra side ' &
            //'by side, one row per period (horizontal, in g)', 'input: '//trim(path), &
            'periods: '//cfg%grid, code_lines(cfg), notes]
        call write_tables(prefix, 'spectra', comments, spectra_columns(cfg), col_units, &
                          table, files_out, stat, errmsg)
    end subroutine write_spectra

    !> The header lines of the suite tables: what, the input, the target, the rule, the
    !> records (computed once for the four tables; each adds its first line).
    function suite_comments(path, cfg, outs, res) result(comments)
        character(len=*), intent(in) :: path
        type(config_t), intent(in) :: cfg
        type(record_out_t), intent(in) :: outs(:)
        type(suite_res_t), intent(in) :: res
        character(len=4096), allocatable :: comments(:)
        character(len=:), allocatable :: line, t0
        integer :: ir, nfailed

        t0 = merge('a_g S     ', 'gamma_I A ', cfg%target /= CODE_EAK)
        nfailed = count(.not. outs%ok)
        comments = [character(len=4096) :: 'input: '//trim(path), &
            'target: the '//trim(upper(code_names(cfg%target)))//' elastic spectrum at 5 % ' &
            //'damping; at T = 0 ('//trim(t0)//'): '//g6(res%target_pga)//' g', &
            code_lines(cfg), &
            'EN 1998-1 3.2.3.1.2(4): (a) at least 3 records; (b) mean PGA >= the target ' &
            //'at T = 0 ('//trim(t0)//'); (c) mean 5 % PSA >= 0.9 target over [0.2 T1, ' &
            //'2 T1] = ['//g6(0.2_dp * cfg%t1)//', '//g6(2.0_dp * cfg%t1) &
            //'] s (structure period T1 = '//g6(cfg%t1)//' s, &suite); 4.3.3.4.3(3): with ' &
            //'7 or more records the mean response should be used (mean_allowed), otherwise ' &
            //'the most unfavourable response', &
            'check grid: '//int_str(size(res%grid))//' periods, '//int_str(cfg%n_points) &
            //' log-spaced from 0.2 T1 to 2 T1 with T1, the target''s corner periods and ' &
            //'the least ratios refined between them (doc/record-suites.md section 2); PSA: ' &
            //'5 % damping, exact peaks over the record, ' &
            //'g = '//shortest_str(STANDARD_GRAVITY)//' m/s2', &
            'common_scale: the smallest factor on every record making (b) and (c) hold ' &
            //'(M.1, doc/record-suites.md; common_rule: the rule that sets it, pga (b) or ' &
            //'spectrum (c)); own_scale: each record''s own factor, '//fit_text(cfg%fit) &
            //' over the grid; own_*: the suite with each record scaled by its own factor', &
            'common_scale and own_scale apply on top of the &records scaling (scale or ' &
            //'target_pga, and polarity): the factor on the file as read is scale x ' &
            //'common_scale (common_total) or scale x own_scale (own_total), per record ' &
            //'in the records table']
        if (nfailed > 0) comments = [character(len=4096) :: comments, 'CHECK FAILS: made ' &
            //'on '//int_str(size(outs) - nfailed)//' of '//int_str(size(outs)) &
            //' records listed (failed: '//failed_records(outs, .not. outs%ok)//'): the ' &
            //'suite checked is not the one listed']
        if (.not. res%done) comments = [character(len=4096) :: comments, 'NO CHECK: '//res%why]
        if (len(cfg%records_from) > 0) comments = [character(len=4096) :: comments, &
            'records from &records of '//cfg%records_from]
        comments = [character(len=4096) :: comments, 'records (index, file, format read, ' &
            //'npts, dt (s), PGA as read (g), scale factor with the polarity):']
        do ir = 1, size(outs)
            if (outs(ir)%ok) then
                line = record_line(ir, cfg%recs(ir), outs(ir))
            else
                line = 'record '//int_str(ir)//': '//cfg%recs(ir)%file//': FAILED: ' &
                       //without_path(outs(ir)%message, cfg%recs(ir)%path)
            end if
            comments = [character(len=4096) :: comments, line]
        end do
    end function suite_comments

    !> The one-row summary of the check. With a record that failed the check fails
    !> (check and own_check fail, status failed): the suite checked is not the one listed.
    subroutine write_summary(prefix, cfg, outs, res, head, files_out, stat, errmsg)
        character(len=*), intent(in) :: prefix
        type(config_t), intent(in) :: cfg
        type(record_out_t), intent(in) :: outs(:)
        type(suite_res_t), intent(in) :: res
        character(len=*), intent(in) :: head(:)
        character(len=*), intent(out) :: files_out(2)
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        integer, parameter :: nc = 26
        real(dp) :: row(1, nc), nan
        character(len=40) :: kinds(nc)
        logical :: all_read

        nan = ieee_value(nan, ieee_quiet_nan)
        all_read = all(outs%ok)
        row = nan
        row(1, 1:5) = [real(size(outs), dp), real(count(.not. outs%ok), dp), &
                       real(count(outs%ok), dp), real(cfg%target - 1, dp), &
                       real(cfg%fit - SUITE_FIT_LINEAR, dp)]
        row(1, 6:9) = [cfg%t1, 0.2_dp * cfg%t1, 2.0_dp * cfg%t1, real(size(res%grid), dp)]
        row(1, 11) = res%target_pga
        row(1, nc) = 1.0_dp
        if (res%done) then
            associate (c => res%check)
                row(1, 3) = real(c%n_records, dp)
                row(1, 6:8) = [c%t1, c%t_low, c%t_high]
                row(1, 10:25) = [c%pga_mean, c%pga_target, c%pga_ratio, flag(c%pga_ok), &
                    c%min_ratio, c%t_min_ratio, flag(c%spectrum_ok), flag(c%count_ok), &
                    flag(c%mean_allowed), flag(c%passed .and. all_read), c%common_scale, &
                    merge(0.0_dp, 1.0_dp, c%scale_rule == SUITE_RULE_PGA), &
                    c%own_pga_ratio, c%own_min_ratio, c%own_t_min_ratio, &
                    flag(c%own_passed .and. all_read)]
            end associate
            row(1, nc) = merge(0.0_dp, 1.0_dp, all_read)
        end if
        kinds = ''
        kinds([1, 2, 3, 9]) = 'int'
        kinds(4) = category_kind(code_names_upper)
        kinds(5) = category_kind(fit_names)
        kinds([13, 16, 17, 19, 25]) = category_kind(check_names)
        kinds(18) = category_kind(yes_names)
        kinds(21) = category_kind(rule_names)
        kinds(nc) = category_kind(status_names)
        call write_tables(prefix, 'suite', [character(len=4096) :: 'seispulse analysis ' &
            //'spectra: the check of a suite of records against a code''s elastic spectrum ' &
            //'(EN 1998-1 3.2.3.1.2(4))', head, 'n_listed: records listed; n_failed: ' &
            //'records that could not be read or that the check refuses (zero PGA or ' &
            //'PSA; then check and own_check fail, status failed); n_records: records ' &
            //'checked; n_periods: the check grid; ' &
            //'common_rule: pga (b) or spectrum (c) sets common_scale; own_t_min_ratio: ' &
            //'the period of own_min_ratio (s)'], &
            [character(len=15) :: 'n_listed', 'n_failed', 'n_records', 'target', 'fit', &
             't1', 't_low', 't_high', 'n_periods', 'pga_mean', 'pga_target', 'pga_ratio', &
             'pga_check', 'min_ratio', 't_min_ratio', 'spectrum_check', 'count_check', &
             'mean_allowed', 'check', 'common_scale', 'common_rule', 'own_pga_ratio', &
             'own_min_ratio', 'own_t_min_ratio', 'own_check', 'status'], &
            [character(len=2) :: '-', '-', '-', '-', '-', 's', 's', 's', '-', 'g', 'g', '-', &
             '-', '-', 's', '-', '-', '-', '-', '-', '-', '-', '-', 's', '-', '-'], &
            row, files_out, stat, errmsg, kinds=kinds, summary=.true.)
    end subroutine write_summary

    !> One row per record: its index, the &records factor, PGA, own scale factor, the
    !> total factors on the file as read, PSA at T1, status.
    subroutine write_records(prefix, outs, res, head, files_out, stat, errmsg)
        character(len=*), intent(in) :: prefix
        type(record_out_t), intent(in) :: outs(:)
        type(suite_res_t), intent(in) :: res
        character(len=*), intent(in) :: head(:)
        character(len=*), intent(out) :: files_out(2)
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        real(dp), allocatable :: table(:, :)
        character(len=label_len(outs)), allocatable :: labels(:)
        real(dp) :: nan, common
        integer :: ir, n

        nan = ieee_value(nan, ieee_quiet_nan)
        common = nan
        if (res%done) common = res%check%common_scale
        n = size(outs)
        allocate(table(n, 8), labels(n))
        do ir = 1, n
            labels(ir) = outs(ir)%name
            table(ir, :) = [real(ir, dp), merge(outs(ir)%factor, nan, outs(ir)%ok), &
                            res%pga(ir), res%own_scale(ir), &
                            outs(ir)%factor * res%own_scale(ir), outs(ir)%factor * common, &
                            res%psa(res%i_t1, ir), merge(0.0_dp, 1.0_dp, outs(ir)%ok)]
            if (.not. outs(ir)%ok) table(ir, 5:6) = nan
        end do
        call write_tables(prefix, 'suite_records', [character(len=4096) :: &
            'seispulse analysis spectra: the records of the check, one row per record', &
            head, 'index: the record''s place in &records files; scale: the &records factor ' &
            //'with the polarity; pga: after scaling; own_scale: the record''s own factor ' &
            //'(NaN without a check); own_total = scale x own_scale and common_total = ' &
            //'scale x common_scale: the factors on the file as read; psa_t1: 5 % PSA at ' &
            //'T1; status: ok, or failed (nan; the reason above and on stderr; exit status 1)'], &
            [character(len=12) :: 'name', 'index', 'scale', 'pga', 'own_scale', 'own_total', &
             'common_total', 'psa_t1', 'status'], &
            [character(len=1) :: '-', '-', '-', 'g', '-', '-', '-', 'g', '-'], table, &
            files_out, stat, errmsg, labels=labels, kinds=[character(len=16) :: '', 'int', &
            '', '', '', '', '', '', category_kind(status_names)])
    end subroutine write_records

    !> On the check grid: the target, 0.9 target, the mean of the suite, their ratio, the
    !> mean scaled by common_scale and the mean of the records scaled by their own factors.
    subroutine write_mean(prefix, res, head, files_out, stat, errmsg)
        character(len=*), intent(in) :: prefix
        type(suite_res_t), intent(in) :: res
        character(len=*), intent(in) :: head(:)
        character(len=*), intent(out) :: files_out(2)
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        real(dp), allocatable :: table(:, :)
        real(dp) :: nan
        integer :: np

        nan = ieee_value(nan, ieee_quiet_nan)
        np = size(res%grid)
        allocate(table(np, 7))
        table = nan
        table(:, 1) = res%grid
        table(:, 2) = res%target
        table(:, 3) = SUITE_SPECTRUM_FRACTION * res%target
        if (res%done) then
            table(:, 4) = res%mean
            table(:, 5) = res%ratio
            table(:, 6) = res%check%common_scale * res%mean
            table(:, 7) = res%own_mean
        end if
        call write_tables(prefix, 'suite_mean', [character(len=4096) :: &
            'seispulse analysis spectra: the mean spectrum of the suite against the target, ' &
            //'one row per period of the check grid', head, 'target_90 = 0.9 target; ' &
            //'mean: the mean 5 % PSA of the records read; ratio = mean/target; ' &
            //'mean_common = common_scale x mean; mean_own: the mean of the records each ' &
            //'scaled by its own_scale'], &
            [character(len=11) :: 'period', 'target', 'target_90', 'mean', 'ratio', &
             'mean_common', 'mean_own'], &
            [character(len=1) :: 's', 'g', 'g', 'g', '-', 'g', 'g'], table, files_out, stat, &
            errmsg)
    end subroutine write_mean

    !> Long format: one row per record and period of the check grid.
    subroutine write_long(prefix, outs, res, head, files_out, stat, errmsg)
        character(len=*), intent(in) :: prefix
        type(record_out_t), intent(in) :: outs(:)
        type(suite_res_t), intent(in) :: res
        character(len=*), intent(in) :: head(:)
        character(len=*), intent(out) :: files_out(2)
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        real(dp), allocatable :: table(:, :)
        character(len=label_len(outs)), allocatable :: labels(:)
        integer :: np, ir, r1, r2

        np = size(res%grid)
        allocate(table(np * size(outs), 5), labels(np * size(outs)))
        do ir = 1, size(outs)
            r1 = (ir - 1) * np + 1
            r2 = ir * np
            labels(r1:r2) = outs(ir)%name
            table(r1:r2, 1) = real(ir, dp)
            table(r1:r2, 2) = res%grid
            table(r1:r2, 3) = res%psa(:, ir)
            table(r1:r2, 4) = res%own_scale(ir) * res%psa(:, ir)
            table(r1:r2, 5) = merge(0.0_dp, 1.0_dp, outs(ir)%ok)
        end do
        call write_tables(prefix, 'suite_spectra', [character(len=4096) :: &
            'seispulse analysis spectra: the 5 % PSA of each record on the check grid, one ' &
            //'row per record and period', head, 'index: the record''s place in &records ' &
            //'files (names can repeat); psa: as the record was scaled by &records; ' &
            //'psa_own = own_scale x psa'], &
            [character(len=7) :: 'name', 'index', 'period', 'psa', 'psa_own', 'status'], &
            [character(len=1) :: '-', '-', 's', 'g', 'g', '-'], table, files_out, stat, &
            errmsg, labels=labels, kinds=[character(len=16) :: '', 'int', '', '', '', &
            category_kind(status_names)])
    end subroutine write_long

    ! ------------------------------------------------------------------------------
    ! Helpers
    ! ------------------------------------------------------------------------------

    !> Whether x is finite and in [lo, hi] (lo excluded with open_lo, hi with open_hi);
    !> else errmsg = where//"name = x: rule" (false).
    logical function in_range(where, name, x, lo, hi, open_lo, errmsg, rule, open_hi)
        character(len=*), intent(in) :: where, name, rule
        real(dp), intent(in) :: x, lo, hi
        logical, intent(in) :: open_lo
        character(len=:), allocatable, intent(inout) :: errmsg
        logical, intent(in), optional :: open_hi
        logical :: hi_open
        hi_open = .false.
        if (present(open_hi)) hi_open = open_hi
        in_range = .not. outside(x, lo, hi, open_lo, hi_open)
        if (.not. in_range) errmsg = where//name//' = '//shortest_str(x)//': '//rule
    end function in_range

    !> The reason of a library message "name = value: reason" (the driver names the key
    !> and the value as the input wrote them).
    function reason(msg) result(s)
        character(len=*), intent(in) :: msg
        character(len=:), allocatable :: s
        integer :: k
        k = index(msg, ': ')
        if (k == 0) then
            s = trim(msg)
        else
            s = trim(msg(k + 2:))
        end if
    end function reason

    !> The message of a record that failed without its path in front (the table's header
    !> line names the file already).
    function without_path(msg, path) result(s)
        character(len=*), intent(in) :: msg, path
        character(len=:), allocatable :: s
        integer :: k
        s = msg
        if (len(s) > len(path) + 2) then
            if (s(1:len(path) + 2) == path//': ') s = s(len(path) + 3:)
        end if
        ! the compiler's "Cannot open file '<path>': " in the system message
        k = index(s, 'Cannot open file '''//path//''': ')
        if (k > 0) s = s(:k - 1)//s(k + len(path) + 21:)
    end function without_path

    !> x to 6 significant digits (the header notes; the tables hold every digit).
    function g6(x) result(s)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: s
        s = g_str(x, 6)
    end function g6

    !> The EAK long-period exponent: '2/3' for the default, else to 6 digits.
    function exponent_text(x) result(s)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: s
        if (.not. (abs(x - 2.0_dp / 3.0_dp) > 0.0_dp)) then
            s = '2/3'
        else
            s = g6(x)
        end if
    end function exponent_text

    !> The EN 1998-1 spectrum type of an EC8 code (CODE_EC8_1, CODE_EC8_2).
    pure integer function ec8_type(code)
        integer, intent(in) :: code
        ec8_type = merge(EC8_SPECTRUM_TYPE_1, EC8_SPECTRUM_TYPE_2, code == CODE_EC8_1)
    end function ec8_type

    !> The column names of the spectra table: period, then per code elastic and/or
    !> design, in the order spectra_table computes them.
    function spectra_columns(cfg) result(names)
        type(config_t), intent(in) :: cfg
        character(len=16), allocatable :: names(:)
        integer :: i, j
        names = [character(len=16) :: 'period']
        do i = 1, size(cfg%codes)
            do j = 1, 2
                if (cfg%kind /= 3 .and. cfg%kind /= j) cycle
                names = [character(len=16) :: names, trim(code_names(cfg%codes(i)))//'_' &
                         //trim(kind_names(j))]
            end do
        end do
    end function spectra_columns

    !> 1 for .true., 0 for .false. (a category code).
    elemental real(dp) function flag(x)
        logical, intent(in) :: x
        flag = merge(1.0_dp, 0.0_dp, x)
    end function flag

    !> "A, B, C" of names in upper case.
    pure function upper_list(names) result(s)
        character(len=*), intent(in) :: names(:)
        character(len=:), allocatable :: s
        s = trim(upper(join(names)))
    end function upper_list

    !> The formula of the own scale factors.
    function fit_text(fit) result(s)
        integer, intent(in) :: fit
        character(len=:), allocatable :: s
        if (fit == SUITE_FIT_LINEAR) then
            s = 'sum(psa target)/sum(psa^2) (M.2)'
        else
            s = 'exp(mean(ln target - ln psa)) (M.3)'
        end if
    end function fit_text

    !> The zone's name in its map (Z1.., I..).
    function zone_name(p) result(s)
        type(eak_t), intent(in) :: p
        character(len=:), allocatable :: s
        if (p%zone_map == EAK_MAP_2003) then
            s = trim(upper(ec8_zones(p%zone)))
        else
            s = trim(upper(eak_zones_2000(p%zone)))
        end if
    end function zone_name

end module driver_spectra
