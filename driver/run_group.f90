!> The &run group: which analysis, and the prefix of the output files.
module driver_run_group
    implicit none
    private

    public :: run_analysis, run_output, read_run, run_keys, write_run
    public :: run_verbose
    public :: run_digits, run_csv_digits, check_run_digits
    public :: run_restart

    character(len=10), parameter :: run_keys(6) = [character(len=10) :: 'analysis', 'output', &
        'verbose', 'digits', 'csv_digits', 'restart']

    character(len=32) :: analysis = ''
    character(len=1024) :: output = ''
    !> significant digits of the numbers in text tables (1..17)
    integer :: digits = 6
    !> significant digits in CSV tables: 0 = the shortest text that reads back to the same
    !> double (round-trip exact), 1..17 = that many
    integer :: csv_digits = 0
    namelist /run/ analysis, output
    !> Also echo the effective input on standard output (it always goes to its file).
    logical :: verbose = .false.
    namelist /run/ verbose
    namelist /run/ digits, csv_digits
    !> Resume a killed run of a batch analysis ('newmark', 'sdof') from its journal
    !> <output>.journal (driver_batch): the units found there are not computed again.
    logical :: restart = .false.
    namelist /run/ restart

contains

    !> Reader for driver_input's read_group.
    subroutine read_run(unit, text, ios, iomsg)
        integer, intent(in) :: unit
        character(len=*), intent(in) :: text
        integer, intent(out) :: ios
        character(len=*), intent(inout) :: iomsg
        if (len(text) > 0) then
            read(text, nml=run, iostat=ios, iomsg=iomsg)
        else
            read(unit, nml=run, iostat=ios, iomsg=iomsg)
        end if
    end subroutine read_run

    function run_analysis() result(s)
        character(len=:), allocatable :: s
        s = trim(analysis)
    end function run_analysis

    function run_output() result(s)
        character(len=:), allocatable :: s
        s = trim(output)
    end function run_output

    logical function run_verbose()
        run_verbose = verbose
    end function run_verbose

    !> Whether to resume from the journal of a killed run (restart = .true.).
    logical function run_restart()
        run_restart = restart
    end function run_restart

    !> Significant digits of the numbers in text tables.
    integer function run_digits()
        run_digits = digits
    end function run_digits

    !> Significant digits in CSV tables (0: shortest round-trip text).
    integer function run_csv_digits()
        run_csv_digits = csv_digits
    end function run_csv_digits

    !> digits in 1..17 and csv_digits in 0..17; errmsg names the key ("digits = 0: ...").
    subroutine check_run_digits(stat, errmsg)
        integer, intent(out) :: stat
        character(len=:), allocatable, intent(out) :: errmsg
        character(len=12) :: buf
        stat = 0
        errmsg = ''
        if (digits < 1 .or. digits > 17) then
            write(buf, '(i0)') digits
            stat = 1
            errmsg = 'digits = '//trim(buf)//': must be 1 to 17 (significant digits in ' &
                     //'the text tables)'
        else if (csv_digits < 0 .or. csv_digits > 17) then
            write(buf, '(i0)') csv_digits
            stat = 1
            errmsg = 'csv_digits = '//trim(buf)//': must be 0 (shortest round-trip text) ' &
                     //'to 17'
        end if
    end subroutine check_run_digits

    !> Echo the group (for the log).
    subroutine write_run(unit)
        integer, intent(in) :: unit
        write(unit, nml=run)
    end subroutine write_run

end module driver_run_group
