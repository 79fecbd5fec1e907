!> The &run group: which analysis, and the prefix of the output files.
module driver_run_group
    implicit none
    private

    public :: run_analysis, run_output, read_run, run_keys, write_run
    public :: run_verbose

    character(len=8), parameter :: run_keys(3) = [character(len=8) :: 'analysis', 'output', &
        'verbose']

    character(len=32) :: analysis = ''
    character(len=1024) :: output = ''
    namelist /run/ analysis, output
    !> Also echo the effective input on standard output (it always goes to its file).
    logical :: verbose = .false.
    namelist /run/ verbose

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

    !> Echo the group (for the log).
    subroutine write_run(unit)
        integer, intent(in) :: unit
        write(unit, nml=run)
    end subroutine write_run

end module driver_run_group
