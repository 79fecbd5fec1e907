!> Where the units of a batch run: the driver built with MPI (module driver_parallel, the
!> same interface as parallel.f90, which meson compiles instead when MPI is absent).
!>
!> Started by an MPI launcher (mpirun, mpiexec, srun), every rank runs the driver on the
!> same input; rank 0 (the root) reads journals, prints and writes every output, the other
!> ranks (workers) compute the units the root sends them, their standard output and error
!> going to /dev/null from par_init on. Started without a launcher the driver is a
!> one-process run: MPI is not started at all and par_run_units is the serial build's
!> (OpenMP threads over units, if built with OpenMP).
!>
!> Dynamic load balancing (records differ in length by orders of magnitude): the root
!> keeps up to `PREFETCH` units assigned to every worker, so that a worker that finishes
!> a unit goes on with the next at once even while the root is inside a long unit of its
!> own; between its own units (and, once none is left, waiting) the root receives the
!> results, hands each to `deliver` and assigns the next unit to the worker that sent it.
!> A worker sends each result without waiting for the root to take it (nonblocking sends,
!> at most PREFETCH + 1 in flight).
!>
!> Messages (on a duplicate of MPI_COMM_WORLD): root -> worker, tag TAG_CTRL, one integer:
!> a unit index (>= 1), or 0 = stop (sent exactly once to every worker, at the end of
!> par_run_units or, if the root never got there, by par_finalize). Worker -> root, tag
!> TAG_HEAD, four integers: the unit index, the number of values, the length of the text
!> and of the log (-1: not allocated; DECLINED in place of the number of values: the
!> worker has left the batch and the root computes that unit itself); then the values
!> (TAG_VALUES), the text (TAG_TEXT) and the log (TAG_LOG), each only when non-empty.
module driver_parallel
    use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
    use, intrinsic :: iso_c_binding, only: c_int, c_char, c_null_char
    use mpi_f08, only: MPI_Comm, MPI_Status, MPI_Request, MPI_COMM_WORLD, MPI_INTEGER, &
                       MPI_DOUBLE_PRECISION, MPI_CHARACTER, MPI_ANY_SOURCE, &
                       MPI_STATUS_IGNORE, MPI_STATUSES_IGNORE, MPI_REQUEST_NULL, &
                       MPI_THREAD_FUNNELED, MPI_Init_thread, MPI_Finalize, MPI_Comm_dup, &
                       MPI_Comm_free, MPI_Comm_rank, MPI_Comm_size, MPI_Send, MPI_Recv, &
                       MPI_Isend, MPI_Iprobe, MPI_Probe, MPI_Waitall
    use seispulse, only: dp
    use driver_unit_result, only: unit_result_t, unit_work, unit_deliver, run_units_here
    implicit none
    private

    public :: par_init, par_finalize, par_rank, par_size, par_root, par_mpi_built
    public :: par_run_units, unit_work, unit_deliver


    !> Units a worker holds assigned at most (the one it computes and the next).
    integer, parameter :: PREFETCH = 2
    !> Results a worker may have in flight (sent, not yet taken by the root).
    integer, parameter :: NSLOT = PREFETCH + 1
    integer, parameter :: TAG_CTRL = 1, TAG_HEAD = 2, TAG_VALUES = 3, TAG_TEXT = 4, &
                          TAG_LOG = 5
    !> In the header in place of the number of values: the worker declined the unit.
    integer, parameter :: DECLINED = -2

    !> Environment variables one of which every MPI launcher sets in its processes
    !> (Open MPI's mpirun, MPICH/Intel hydra, MVAPICH, Slurm's srun, PMIx launchers).
    character(len=20), parameter :: launcher_vars(7) = [character(len=20) :: &
        'OMPI_COMM_WORLD_SIZE', 'PMIX_RANK', 'PMI_RANK', 'PMI_SIZE', 'PMI_FD', &
        'MV2_COMM_WORLD_RANK', 'SLURM_PROCID']

    !> A result being sent by a worker (its buffers live until the sends complete).
    type :: slot_t
        integer :: head(4) = 0
        real(dp), allocatable :: values(:)
        character(len=:), allocatable :: text
        character(len=:), allocatable :: log
        type(MPI_Request) :: req(4)
        logical :: busy = .false.
    end type slot_t

    logical :: mpi_on = .false.          !! MPI started (a launcher started this process)
    logical :: finalized = .false.       !! par_finalize done
    logical :: stopped = .false.         !! the stop message is sent (root) / received (worker)
    integer :: rank = 0, nproc = 1
    type(MPI_Comm) :: comm
    type(slot_t), asynchronous, save :: slots(NSLOT)
    integer :: last_slot = 0

    interface
        ! POSIX open() with two arguments (no O_CREAT: the mode argument is not passed)
        integer(c_int) function c_open(path, flags) bind(c, name='open')
            import :: c_int, c_char
            character(kind=c_char), intent(in) :: path(*)
            integer(c_int), value, intent(in) :: flags
        end function c_open
        ! POSIX dup2(): fd `old` also as `new`
        integer(c_int) function c_dup2(old, new) bind(c, name='dup2')
            import :: c_int
            integer(c_int), value, intent(in) :: old, new
        end function c_dup2
        ! POSIX close()
        integer(c_int) function c_close(fd) bind(c, name='close')
            import :: c_int
            integer(c_int), value, intent(in) :: fd
        end function c_close
    end interface

contains

    !> Start: MPI_Init (thread level funneled: only the main thread calls MPI) when an MPI
    !> launcher started this process, else nothing (a one-process run). On a rank other
    !> than 0, standard output and error go to /dev/null from here on.
    subroutine par_init()
        integer :: provided
        if (mpi_on .or. finalized) return
        if (.not. launched()) return
        call MPI_Init_thread(MPI_THREAD_FUNNELED, provided)
        mpi_on = .true.
        call MPI_Comm_dup(MPI_COMM_WORLD, comm)
        call MPI_Comm_rank(comm, rank)
        call MPI_Comm_size(comm, nproc)
        if (rank /= 0) call silence()
    end subroutine par_init

    !> End (MPI_Finalize); call once, before exit. The root first tells every worker that
    !> has not been told to stop; a worker waits for that message, declining the units
    !> the root still sends it (the root computes them itself).
    subroutine par_finalize()
        type(unit_result_t) :: none
        integer :: w, idx
        if (.not. mpi_on .or. finalized) return
        if (.not. stopped) then
            if (rank == 0) then
                do w = 1, nproc - 1
                    call MPI_Send(0, 1, MPI_INTEGER, w, TAG_CTRL, comm)
                end do
            else
                do
                    call MPI_Recv(idx, 1, MPI_INTEGER, 0, TAG_CTRL, comm, MPI_STATUS_IGNORE)
                    if (idx <= 0) exit
                    call send_result(idx, none, decline=.true.)
                end do
            end if
            stopped = .true.
        end if
        call wait_slots()
        call MPI_Comm_free(comm)
        call MPI_Finalize()
        finalized = .true.
        mpi_on = .false.
    end subroutine par_finalize

    !> This process's rank (0-based).
    integer function par_rank()
        par_rank = rank
    end function par_rank

    !> The number of processes.
    integer function par_size()
        par_size = nproc
    end function par_size

    !> Whether this process is the root (reads journals, writes every output).
    logical function par_root()
        par_root = rank == 0
    end function par_root

    !> Whether this driver was built with MPI.
    logical function par_mpi_built()
        par_mpi_built = .true.
    end function par_mpi_built

    !> Compute the units `todo` (indices, on the root; other ranks get theirs from the
    !> root) and hand each result to `deliver` on the root. On a worker it returns when
    !> the root says there are no more units (`todo` and `deliver` are not used there).
    subroutine par_run_units(todo, work, deliver)
        integer, intent(in) :: todo(:)
        procedure(unit_work) :: work
        procedure(unit_deliver) :: deliver
        if (.not. mpi_on .or. nproc == 1) then
            call run_units_here(todo, work, deliver)
        else if (rank == 0) then
            call run_root(todo, work, deliver)
        else
            call run_worker(work)
        end if
    end subroutine par_run_units


    !> The root: assign, compute its own share, receive and deliver, then stop the workers.
    subroutine run_root(todo, work, deliver)
        integer, intent(in) :: todo(:)
        procedure(unit_work) :: work
        procedure(unit_deliver) :: deliver
        type(unit_result_t) :: res
        type(MPI_Status) :: status
        logical :: alive(nproc - 1), arrived
        integer :: back(size(todo))      ! units declined by a worker: the root's own
        integer :: n, next, done, nback, w, round, i
        n = size(todo)
        alive = .not. stopped
        next = 1
        done = 0
        nback = 0
        do round = 1, PREFETCH
            do w = 1, nproc - 1
                if (alive(w)) call give_next(w)
            end do
        end do
        do while (done < n)
            do
                call MPI_Iprobe(MPI_ANY_SOURCE, TAG_HEAD, comm, arrived, status)
                if (.not. arrived) exit
                call take(status%MPI_SOURCE)
            end do
            if (nback > 0 .or. next <= n) then
                if (nback > 0) then
                    i = back(nback)
                    nback = nback - 1
                else
                    i = todo(next)
                    next = next + 1
                end if
                call work(i, res)
                call deliver(i, res)
                done = done + 1
            else if (done < n) then
                call MPI_Probe(MPI_ANY_SOURCE, TAG_HEAD, comm, status)
                call take(status%MPI_SOURCE)
            end if
        end do
        if (.not. stopped) then
            do w = 1, nproc - 1
                call MPI_Send(0, 1, MPI_INTEGER, w, TAG_CTRL, comm)
            end do
            stopped = .true.
        end if
    contains
        !> The next unit to worker w, if any is left.
        subroutine give_next(w)
            integer, intent(in) :: w
            if (next > n) return
            call MPI_Send(todo(next), 1, MPI_INTEGER, w, TAG_CTRL, comm)
            next = next + 1
        end subroutine give_next
        !> Receive the result worker w sent (its header has arrived), deliver it, and
        !> assign w its next unit.
        subroutine take(w)
            integer, intent(in) :: w
            type(unit_result_t) :: got
            integer :: head(4)
            call MPI_Recv(head, 4, MPI_INTEGER, w, TAG_HEAD, comm, MPI_STATUS_IGNORE)
            if (head(2) == DECLINED) then
                alive(w) = .false.
                nback = nback + 1
                back(nback) = head(1)
                return
            end if
            if (head(2) >= 0) then
                allocate(got%values(head(2)))
                if (head(2) > 0) call MPI_Recv(got%values, head(2), MPI_DOUBLE_PRECISION, &
                                               w, TAG_VALUES, comm, MPI_STATUS_IGNORE)
            end if
            if (head(3) >= 0) then
                allocate(character(len=head(3)) :: got%text)
                if (head(3) > 0) call MPI_Recv(got%text, head(3), MPI_CHARACTER, w, &
                                               TAG_TEXT, comm, MPI_STATUS_IGNORE)
            end if
            if (head(4) >= 0) then
                allocate(character(len=head(4)) :: got%log)
                if (head(4) > 0) call MPI_Recv(got%log, head(4), MPI_CHARACTER, w, &
                                               TAG_LOG, comm, MPI_STATUS_IGNORE)
            end if
            call deliver(head(1), got)
            done = done + 1
            call give_next(w)
        end subroutine take
    end subroutine run_root

    !> A worker: compute the units the root sends until it says stop.
    subroutine run_worker(work)
        procedure(unit_work) :: work
        type(unit_result_t) :: res
        integer :: idx
        do while (.not. stopped)
            call MPI_Recv(idx, 1, MPI_INTEGER, 0, TAG_CTRL, comm, MPI_STATUS_IGNORE)
            if (idx <= 0) then
                stopped = .true.
            else
                call work(idx, res)
                call send_result(idx, res)
            end if
        end do
        call wait_slots()
    end subroutine run_worker

    !> Send the result of unit idx to the root without waiting for it to be taken (the
    !> oldest result in flight is waited for when every slot is busy). `res` is moved
    !> into the slot (unallocated on return).
    subroutine send_result(idx, res, decline)
        integer, intent(in) :: idx
        type(unit_result_t), intent(inout) :: res
        logical, intent(in), optional :: decline
        integer :: s
        s = mod(last_slot, NSLOT) + 1
        last_slot = s
        if (slots(s)%busy) call MPI_Waitall(4, slots(s)%req, MPI_STATUSES_IGNORE)
        slots(s)%busy = .true.
        slots(s)%req = MPI_REQUEST_NULL
        if (allocated(slots(s)%values)) deallocate(slots(s)%values)
        if (allocated(slots(s)%text)) deallocate(slots(s)%text)
        if (allocated(slots(s)%log)) deallocate(slots(s)%log)
        if (allocated(res%values)) call move_alloc(res%values, slots(s)%values)
        if (allocated(res%text)) call move_alloc(res%text, slots(s)%text)
        if (allocated(res%log)) call move_alloc(res%log, slots(s)%log)
        slots(s)%head = [idx, -1, -1, -1]
        if (allocated(slots(s)%values)) slots(s)%head(2) = size(slots(s)%values)
        if (allocated(slots(s)%text)) slots(s)%head(3) = len(slots(s)%text)
        if (allocated(slots(s)%log)) slots(s)%head(4) = len(slots(s)%log)
        if (present(decline)) then
            if (decline) slots(s)%head(2:4) = [DECLINED, -1, -1]
        end if
        call MPI_Isend(slots(s)%head, 4, MPI_INTEGER, 0, TAG_HEAD, comm, slots(s)%req(1))
        if (slots(s)%head(2) > 0) call MPI_Isend(slots(s)%values, slots(s)%head(2), &
            MPI_DOUBLE_PRECISION, 0, TAG_VALUES, comm, slots(s)%req(2))
        if (slots(s)%head(3) > 0) call MPI_Isend(slots(s)%text, slots(s)%head(3), &
            MPI_CHARACTER, 0, TAG_TEXT, comm, slots(s)%req(3))
        if (slots(s)%head(4) > 0) call MPI_Isend(slots(s)%log, slots(s)%head(4), &
            MPI_CHARACTER, 0, TAG_LOG, comm, slots(s)%req(4))
    end subroutine send_result

    !> Wait until every result in flight has been taken by the root.
    subroutine wait_slots()
        integer :: s
        do s = 1, NSLOT
            if (slots(s)%busy) call MPI_Waitall(4, slots(s)%req, MPI_STATUSES_IGNORE)
            slots(s)%busy = .false.
        end do
    end subroutine wait_slots

    !> Whether an MPI launcher started this process (one of launcher_vars is set).
    logical function launched()
        integer :: k, st
        launched = .false.
        do k = 1, size(launcher_vars)
            call get_environment_variable(trim(launcher_vars(k)), status=st)
            if (st == 0) then
                launched = .true.
                return
            end if
        end do
    end function launched

    !> Standard output and error to /dev/null (a worker prints nothing).
    subroutine silence()
        integer(c_int), parameter :: O_WRONLY = 1_c_int
        integer(c_int) :: fd, rc
        flush(output_unit)
        flush(error_unit)
        fd = c_open('/dev/null'//c_null_char, O_WRONLY)
        if (fd < 0) return
        rc = c_dup2(fd, 1_c_int)
        rc = c_dup2(fd, 2_c_int)
        if (fd > 2) rc = c_close(fd)
    end subroutine silence

end module driver_parallel
