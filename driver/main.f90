!> seispulse batch driver: `seispulse FILE.nml`.
!>
!> Reads &run (analysis, output) and the groups of that analysis, echoes the
!> effective input, writes the tables and says where they went. Any problem is one
!> line on stderr naming file, line, group, key and problem, and exit status 2.
!> Analyses 'newmark', 'sdof', 'cylinder', 'winkler' (a history on records), 'empirical'
!> (on records) and 'spectra' (the record-suite check) go on past a record that cannot be
!> read: its rows fail, the tables are written with all rows, and the exit status is 1.
program seispulse_driver
    use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
    use, intrinsic :: iso_c_binding, only: c_int
    use driver_namelist_scan, only: nml_group, scan_file, lower
    use driver_input, only: find_group, check_keys, read_group, located, join, ROWS_FAILED, &
                            set_run_line
    use driver_input, only: output_located
    use driver_pulse, only: run_pulse, pulse_groups, pulse_tables
    use driver_sliding, only: run_sliding, sliding_groups, sliding_tables
    use driver_rocking, only: run_rocking, rocking_groups, rocking_tables
    use driver_newmark, only: run_newmark, newmark_groups, newmark_tables
    use driver_sdof, only: run_sdof, sdof_groups, sdof_tables
    use driver_sdof_beta, only: run_sdof_beta, sdof_beta_groups, sdof_beta_tables
    use driver_sdof_shock, only: run_sdof_shock, sdof_shock_groups, sdof_shock_tables
    use driver_walls, only: run_walls, walls_groups, walls_tables
    use driver_cylinder, only: run_cylinder, cylinder_groups, cylinder_tables
    use driver_winkler, only: run_winkler, winkler_groups, winkler_tables
    use driver_empirical, only: run_empirical, empirical_groups, empirical_tables
    use driver_spectra, only: run_spectra, spectra_groups, spectra_tables
    use driver_run_group, only: run_analysis, run_output, read_run, run_keys, write_run, &
                                run_verbose, check_run_digits, run_restart
    use driver_echo, only: echo_unit, echo_start, echo_finish, echo_file_path
    use driver_tables, only: commit_outputs, discard_outputs
    use driver_parallel, only: par_init, par_finalize, par_root
    use driver_batch, only: batch_commit, batch_discard
    implicit none

    interface
        ! C exit(): the status without gfortran's "STOP 2" line (stop prints it).
        subroutine c_exit(status) bind(c, name='exit')
            import :: c_int
            integer(c_int), value, intent(in) :: status
        end subroutine c_exit
    end interface

    !> Exit status: success; tables written but some rows failed; an input or output
    !> error (nothing written, and the tables of an earlier run with this prefix removed).
    integer, parameter :: EXIT_OK = 0, EXIT_ROWS_FAILED = 1, EXIT_INPUT_ERROR = 2

    character(len=10), parameter :: analyses(12) = [character(len=10) :: 'pulse', 'sliding', &
        'rocking', 'newmark', 'sdof', 'sdof_beta', 'sdof_shock', 'walls', 'cylinder', 'winkler', &
        'empirical', 'spectra']
    !> Every group of any analysis (besides run), for the first check.
    character(len=12), parameter :: all_groups(26) = [character(len=12) :: 'pulse', 'time', &
        'block', 'method', 'history', 'rocking', 'map', 'records', 'newmark', 'sdof', &
        'sdof_history', 'sdof_beta', 'sdof_shock', 'wall', 'backfill', 'seismic', 'body', &
        'cylinder', 'roll', 'winkler', 'empirical', 'slope', 'spectra', 'ec8', 'eak', 'suite']

    character(len=:), allocatable :: path, errmsg
    !> the tables any analysis may write: after an input error, those of the prefix are
    !> removed whatever the analysis (a stale table of another analysis must not remain
    !> next to a missing echo file)
    character(len=32), parameter :: all_tables(*) = [character(len=32) :: pulse_tables, &
        sliding_tables, rocking_tables, newmark_tables, sdof_tables, sdof_beta_tables, &
        sdof_shock_tables, walls_tables, cylinder_tables, winkler_tables, empirical_tables, &
        spectra_tables]
    character(len=4096) :: arg
    type(nml_group), allocatable :: groups(:)
    integer :: stat, irun, i, j

    ! an MPI job: every rank reads the input; only the root prints and writes
    call par_init()
    if (command_argument_count() /= 1) then
        write(error_unit, '(a)') 'usage: seispulse INPUT.nml   (see README, "Batch driver")'
        call finish(EXIT_INPUT_ERROR)
    end if
    call get_command_argument(1, arg)
    path = trim(arg)

    call scan_file(path, groups, stat, errmsg)
    if (stat /= 0) call fail(errmsg)
    if (size(groups) == 0) call fail(path//':1: no namelist group in the input (empty, or ' &
        //'only comments: it needs &run analysis = ..., output = ... /)')

    ! every group must be known and appear once
    do i = 1, size(groups)
        if (groups(i)%name /= 'run' .and. .not. any(all_groups == groups(i)%name)) &
            call fail(located(path, groups(i))//'unknown group (allowed: run, ' &
                      //join(all_groups)//')')
        do j = 1, i - 1
            if (groups(j)%name == groups(i)%name) &
                call fail(located(path, groups(i))//'group given twice')
        end do
    end do

    irun = find_group(groups, 'run')
    if (irun == 0) call fail(path//':1: &run: missing group (it names the analysis and output)')
    call set_run_line(groups(irun)%line)
    call check_keys(path, groups(irun), run_keys, stat, errmsg)
    if (stat /= 0) call fail(errmsg)
    call read_group(path, groups(irun), read_run, stat, errmsg)
    if (stat /= 0) call fail(errmsg)
    ! another MPI rank takes part in batches only (driver_batch); anything else is the
    ! root's alone
    select case (lower(run_analysis()))
    case ('newmark', 'sdof')
    case default
        if (.not. par_root()) call finish(EXIT_OK)
        if (run_restart() .and. any(analyses == lower(run_analysis()))) &
            write(error_unit, '(a)') 'warning: '//located(path, groups(irun)) &
            //'restart: only the analyses ''newmark'' and ''sdof'' keep a journal to ' &
            //'restart from (ignored)'
    end select
    if (len(run_output()) == 0) call fail(located(path, groups(irun)) &
        //'output: missing (the prefix of the output files, e.g. ''out/case1'')')
    call echo_start(run_output())
    call check_run_digits(stat, errmsg)
    if (stat /= 0) call fail(located(path, groups(irun))//errmsg)

    select case (lower(run_analysis()))
    case ('pulse')
        call start(pulse_groups)
        call run_pulse(path, groups, run_output(), stat, errmsg)
    case ('sliding')
        call start(sliding_groups)
        call run_sliding(path, groups, run_output(), stat, errmsg)
    case ('rocking')
        call start(rocking_groups)
        call run_rocking(path, groups, run_output(), stat, errmsg)
        ! on records: the table is written; some rows failed (each already reported)
        if (stat == ROWS_FAILED) call fail(errmsg, EXIT_ROWS_FAILED)
    case ('newmark')
        call start(newmark_groups)
        call run_newmark(path, groups, run_output(), stat, errmsg)
        ! the table is written; some rows failed (each already reported)
        if (stat == ROWS_FAILED) call fail(errmsg, EXIT_ROWS_FAILED)
    case ('sdof')
        call start(sdof_groups)
        call run_sdof(path, groups, run_output(), stat, errmsg)
        ! the tables are written; some records failed (each already reported)
        if (stat == ROWS_FAILED) call fail(errmsg, EXIT_ROWS_FAILED)
    case ('sdof_beta')
        call start(sdof_beta_groups)
        call run_sdof_beta(path, groups, run_output(), stat, errmsg)
    case ('sdof_shock')
        call start(sdof_shock_groups)
        call run_sdof_shock(path, groups, run_output(), stat, errmsg)
    case ('walls')
        call start(walls_groups)
        call run_walls(path, groups, run_output(), stat, errmsg)
    case ('cylinder')
        call start(cylinder_groups)
        call run_cylinder(path, groups, run_output(), stat, errmsg)
        ! the tables are written; some records failed (each already reported)
        if (stat == ROWS_FAILED) call fail(errmsg, EXIT_ROWS_FAILED)
    case ('winkler')
        call start(winkler_groups)
        call run_winkler(path, groups, run_output(), stat, errmsg)
        ! the tables are written; some records failed (each already reported)
        if (stat == ROWS_FAILED) call fail(errmsg, EXIT_ROWS_FAILED)
    case ('empirical')
        call start(empirical_groups)
        call run_empirical(path, groups, run_output(), stat, errmsg)
        ! the table is written; some rows failed (each already reported)
        if (stat == ROWS_FAILED) call fail(errmsg, EXIT_ROWS_FAILED)
    case ('spectra')
        call start(spectra_groups)
        call run_spectra(path, groups, run_output(), stat, errmsg)
        ! the tables are written; some records failed (each already reported)
        if (stat == ROWS_FAILED) call fail(errmsg, EXIT_ROWS_FAILED)
    case ('')
        call fail(located(path, groups(irun))//'analysis: missing (allowed: '//join(analyses)//')')
    case default
        call fail(located(path, groups(irun))//'analysis = '''//run_analysis() &
                  //''': unknown analysis (allowed: '//join(analyses)//')')
    end select
    if (stat /= 0) call fail(errmsg)
    call write_echo()
    call finish(EXIT_OK)

contains

    !> Before an analysis: every group but &run must belong to it (allowed); then the echo
    !> of &run.
    subroutine start(allowed)
        character(len=*), intent(in) :: allowed(:)
        integer :: k
        do k = 1, size(groups)
            if (groups(k)%name /= 'run' .and. .not. any(allowed == groups(k)%name)) &
                call fail(located(path, groups(k))//'not a group of analysis ''' &
                          //lower(run_analysis())//''' (allowed: run, '//join(allowed)//')')
        end do
        call write_run(echo_unit())
    end subroutine start

    !> The error message, then exit: with `status` (EXIT_ROWS_FAILED: the tables are
    !> written, some rows failed), else EXIT_INPUT_ERROR (nothing written; with verbose,
    !> the echo so far on standard output).
    recursive subroutine fail(message, status)
        character(len=*), intent(in) :: message
        integer, intent(in), optional :: status
        character(len=:), allocatable :: msg
        integer :: st
        if (present(status)) call write_echo()
        write(error_unit, '(a)') 'seispulse: error: '//with_line(message, present(status))
        if (present(status)) call finish(status)
        if (run_verbose()) call echo_finish(path, groups, run_output(), .false., .true., st, msg)
        call finish(EXIT_INPUT_ERROR)
    end subroutine fail

    !> The summary of failed rows (`rows`) placed at &records (else at &suite, whose
    !> records_from names them, else at the analysis' group, else at &run):
    !> "file:line: &group: message"; any other message as it is
    !> (every other message is built with its place: located, output_located).
    function with_line(message, rows) result(text)
        character(len=*), intent(in) :: message
        logical, intent(in) :: rows
        character(len=:), allocatable :: text
        integer :: ig
        text = message
        if (.not. (rows .and. allocated(groups))) return
        ig = find_group(groups, 'records')
        if (ig == 0) ig = find_group(groups, 'suite')
        if (ig == 0) ig = find_group(groups, lower(run_analysis()))
        if (ig == 0) ig = find_group(groups, 'run')
        if (ig > 0) text = located(path, groups(ig))//message
    end function with_line

    !> The echo of the effective input: the file (and standard output with verbose).
    recursive subroutine write_echo()
        character(len=:), allocatable :: msg
        integer :: st
        call echo_finish(path, groups, run_output(), .true., run_verbose(), st, msg)
        if (st /= 0) call fail(msg)
        write(output_unit, '(a)') 'effective input written to '//echo_file_path(run_output())
    end subroutine write_echo

    !> Exit with `status`: the outputs of the run are renamed to their final names
    !> (EXIT_OK, EXIT_ROWS_FAILED; a rename that fails makes it EXIT_INPUT_ERROR) and the
    !> restart journal of a batch removed, or, for EXIT_INPUT_ERROR, the outputs deleted
    !> together with the files of an earlier run of this prefix (and the journal this run
    !> started, unless it is a restart: driver_batch's batch_discard). Another MPI rank than
    !> the root touches no file and exits with 0.
    subroutine finish(status)
        integer, intent(in) :: status
        integer :: st, rc
        character(len=:), allocatable :: msg
        rc = status
        if (.not. par_root()) then
            call par_finalize()
            call c_exit(0_c_int)
        end if
        if (rc /= EXIT_INPUT_ERROR) then
            call commit_outputs(st, msg)
            if (st /= 0) then
                write(error_unit, '(a)') 'seispulse: error: ' &
                    //output_located(path)//msg
                rc = EXIT_INPUT_ERROR
            else
                call batch_commit()
            end if
        end if
        if (rc == EXIT_INPUT_ERROR) then
            call batch_discard()
            ! the input itself (an edited echo file under its own prefix) always stays
            if (allocated(path)) then
                call discard_outputs(run_output(), all_tables, keep=path)
            else
                call discard_outputs('', all_tables)
            end if
        end if
        flush(output_unit)
        flush(error_unit)
        call par_finalize()
        call c_exit(int(rc, c_int))
    end subroutine finish

end program seispulse_driver
