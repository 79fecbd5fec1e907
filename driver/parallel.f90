!> Where the units of a batch run: this is the driver built without MPI, one process;
!> with OpenMP the units are spread over threads (dynamic schedule: records differ in
!> length). parallel_mpi.f90 is the same module for the MPI build. Every unit's result
!> goes to `deliver` on the root, one at a time (never two threads at once), in the order
!> the units finish; the caller makes the output independent of that order.
module driver_parallel
    use driver_unit_result, only: unit_result_t, unit_work, unit_deliver, run_units_here
    implicit none
    private

    public :: par_init, par_finalize, par_rank, par_size, par_root, par_mpi_built
    public :: par_run_units, unit_work, unit_deliver


contains

    !> Start (MPI_Init in the MPI build).
    subroutine par_init()
    end subroutine par_init

    !> End (MPI_Finalize in the MPI build); call once, before exit.
    subroutine par_finalize()
    end subroutine par_finalize

    !> This process's rank (0-based).
    integer function par_rank()
        par_rank = 0
    end function par_rank

    !> The number of processes.
    integer function par_size()
        par_size = 1
    end function par_size

    !> Whether this process is the root (reads journals, writes every output).
    logical function par_root()
        par_root = .true.
    end function par_root

    !> Whether this driver was built with MPI.
    logical function par_mpi_built()
        par_mpi_built = .false.
    end function par_mpi_built

    !> Compute the units `todo` (indices, on the root; other ranks of the MPI build get
    !> theirs from the root) and hand each result to `deliver` on the root.
    subroutine par_run_units(todo, work, deliver)
        integer, intent(in) :: todo(:)
        procedure(unit_work) :: work
        procedure(unit_deliver) :: deliver
        call run_units_here(todo, work, deliver)
    end subroutine par_run_units

end module driver_parallel
