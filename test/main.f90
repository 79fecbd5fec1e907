!> Runs all unit-test suites, or the one named by the first argument.
!> Last line: "N passed, N failed"; exit status 1 on any failure.
program tester
    use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
    use testing, only: unit_test, run_suite
    use test_special, only: collect_special
    use test_divided_differences, only: collect_divided_differences
    use test_roots, only: collect_roots
    use test_fft, only: collect_fft
    use test_intensity, only: collect_intensity
    use test_ode, only: collect_ode
    use test_lapack, only: collect_lapack
    use test_radau, only: collect_radau
    use test_pulses, only: collect_pulses
    use test_sliding_sim, only: collect_sliding_sim
    use test_sliding_closed, only: collect_sliding_closed
    use test_rocking_closed, only: collect_rocking_closed
    use test_rocking_sim, only: collect_rocking_sim
    use test_cylinder, only: collect_cylinder
    use test_cylinder_roll, only: collect_cylinder_roll
    use test_winkler, only: collect_winkler
    use test_clay_footing, only: collect_clay_footing
    use test_winkler_rock, only: collect_winkler_rock
    use test_records, only: collect_records
    use test_number_reader, only: collect_number_reader
    use test_format, only: collect_format
    use test_reentrant, only: collect_reentrant
    use test_newmark, only: collect_newmark
    use test_flexible, only: collect_flexible
    use test_flexible_exact, only: collect_flexible_exact
    use test_sdof_sim, only: collect_sdof_sim
    use test_sdof_closed, only: collect_sdof_closed
    use test_walls_vy, only: collect_walls_vy
    use test_walls_one_term, only: collect_walls_one_term
    use test_codes, only: collect_codes
    use test_record_suite, only: collect_record_suite
    use test_eak2000, only: collect_eak2000
    use test_empirical, only: collect_empirical
    use test_optional_args, only: collect_optional_args
    implicit none
    character(len=64) :: wanted
    integer :: npass, nfail, nrun
    type(unit_test), allocatable :: tests(:)

    wanted = ''
    if (command_argument_count() >= 1) call get_command_argument(1, wanted)
    npass = 0
    nfail = 0
    nrun = 0
    if (selected('special')) then
        call collect_special(tests)
        call run_suite('special', tests, output_unit, npass, nfail)
    end if
    if (selected('divided_differences')) then
        call collect_divided_differences(tests)
        call run_suite('divided_differences', tests, output_unit, npass, nfail)
    end if
    if (selected('roots')) then
        call collect_roots(tests)
        call run_suite('roots', tests, output_unit, npass, nfail)
    end if
    if (selected('format')) then
        call collect_format(tests)
        call run_suite('format', tests, output_unit, npass, nfail)
    end if
    if (selected('reentrant')) then
        call collect_reentrant(tests)
        call run_suite('reentrant', tests, output_unit, npass, nfail)
    end if
    if (selected('fft')) then
        call collect_fft(tests)
        call run_suite('fft', tests, output_unit, npass, nfail)
    end if
    if (selected('intensity')) then
        call collect_intensity(tests)
        call run_suite('intensity', tests, output_unit, npass, nfail)
    end if
    if (selected('ode')) then
        call collect_ode(tests)
        call run_suite('ode', tests, output_unit, npass, nfail)
    end if
    if (selected('radau')) then
        call collect_radau(tests)
        call run_suite('radau', tests, output_unit, npass, nfail)
    end if
    if (selected('lapack')) then
        call collect_lapack(tests)
        call run_suite('lapack', tests, output_unit, npass, nfail)
    end if
    if (selected('pulses')) then
        call collect_pulses(tests)
        call run_suite('pulses', tests, output_unit, npass, nfail)
    end if
    if (selected('sliding_sim')) then
        call collect_sliding_sim(tests)
        call run_suite('sliding_sim', tests, output_unit, npass, nfail)
    end if
    if (selected('sliding_closed')) then
        call collect_sliding_closed(tests)
        call run_suite('sliding_closed', tests, output_unit, npass, nfail)
    end if
    if (selected('rocking_closed')) then
        call collect_rocking_closed(tests)
        call run_suite('rocking_closed', tests, output_unit, npass, nfail)
    end if
    if (selected('rocking_sim')) then
        call collect_rocking_sim(tests)
        call run_suite('rocking_sim', tests, output_unit, npass, nfail)
    end if
    if (selected('cylinder')) then
        call collect_cylinder(tests)
        call run_suite('cylinder', tests, output_unit, npass, nfail)
    end if
    if (selected('cylinder_roll')) then
        call collect_cylinder_roll(tests)
        call run_suite('cylinder_roll', tests, output_unit, npass, nfail)
    end if
    if (selected('winkler')) then
        call collect_winkler(tests)
        call run_suite('winkler', tests, output_unit, npass, nfail)
    end if
    if (selected('clay_footing')) then
        call collect_clay_footing(tests)
        call run_suite('clay_footing', tests, output_unit, npass, nfail)
    end if
    if (selected('winkler_rock')) then
        call collect_winkler_rock(tests)
        call run_suite('winkler_rock', tests, output_unit, npass, nfail)
    end if
    if (selected('records')) then
        call collect_records(tests)
        call run_suite('records', tests, output_unit, npass, nfail)
    end if
    if (selected('number_reader')) then
        call collect_number_reader(tests)
        call run_suite('number_reader', tests, output_unit, npass, nfail)
    end if
    if (selected('newmark')) then
        call collect_newmark(tests)
        call run_suite('newmark', tests, output_unit, npass, nfail)
    end if
    if (selected('flexible')) then
        call collect_flexible(tests)
        call run_suite('flexible', tests, output_unit, npass, nfail)
    end if
    if (selected('flexible_exact')) then
        call collect_flexible_exact(tests)
        call run_suite('flexible_exact', tests, output_unit, npass, nfail)
    end if
    if (selected('sdof_sim')) then
        call collect_sdof_sim(tests)
        call run_suite('sdof_sim', tests, output_unit, npass, nfail)
    end if
    if (selected('sdof_closed')) then
        call collect_sdof_closed(tests)
        call run_suite('sdof_closed', tests, output_unit, npass, nfail)
    end if
    if (selected('walls_vy')) then
        call collect_walls_vy(tests)
        call run_suite('walls_vy', tests, output_unit, npass, nfail)
    end if
    if (selected('walls_one_term')) then
        call collect_walls_one_term(tests)
        call run_suite('walls_one_term', tests, output_unit, npass, nfail)
    end if
    if (selected('codes')) then
        call collect_codes(tests)
        call run_suite('codes', tests, output_unit, npass, nfail)
    end if
    if (selected('record_suite')) then
        call collect_record_suite(tests)
        call run_suite('record_suite', tests, output_unit, npass, nfail)
    end if
    if (selected('eak2000')) then
        call collect_eak2000(tests)
        call run_suite('eak2000', tests, output_unit, npass, nfail)
    end if
    if (selected('empirical')) then
        call collect_empirical(tests)
        call run_suite('empirical', tests, output_unit, npass, nfail)
    end if
    if (selected('optional_args')) then
        call collect_optional_args(tests)
        call run_suite('optional_args', tests, output_unit, npass, nfail)
    end if
    if (nrun == 0) then
        write(error_unit, '(a)') 'unknown suite: '//trim(wanted)
        error stop 2
    end if
    write(output_unit, '(i0, a, i0, a)') npass, ' passed, ', nfail, ' failed'
    if (nfail > 0) error stop 1

contains

    logical function selected(name)
        character(len=*), intent(in) :: name
        selected = len_trim(wanted) == 0 .or. trim(wanted) == name
        if (selected) nrun = nrun + 1
    end function selected

end program tester
