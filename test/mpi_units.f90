!> State and units of the test program mpi_units below (module procedures: passed as
!> arguments, they need no trampoline on the stack).
module mpi_units_lib
    use, intrinsic :: iso_fortran_env, only: output_unit, int64
    use seispulse, only: dp, int_str
    use driver_unit_result, only: unit_result_t, add_field, add_log
    use driver_parallel, only: par_root, par_rank
    implicit none
    private

    public :: NUNIT, delivered, expected, computed, passed, failed
    public :: work, deliver, check_delivered, check

    integer, parameter :: NUNIT = 60
    integer :: delivered(NUNIT) = 0       !! times each unit was delivered (root)
    logical :: expected(NUNIT) = .false.  !! the units of todo
    integer :: computed = 0               !! units computed on this rank
    integer :: passed = 0, failed = 0

contains

    !> The result of unit i, made from i alone (sizes, allocation and contents).
    subroutine make_result(i, res)
        integer, intent(in) :: i
        type(unit_result_t), intent(out) :: res
        integer :: k, nv
        select case (mod(i, 7))
        case (0)
            continue                               ! values not allocated
        case (1)
            allocate(res%values(0))
        case default
            nv = 1 + mod(37 * i, 500)
            if (mod(i, 11) == 2) nv = 100000       ! larger than any eager message
            allocate(res%values(nv))
            do k = 1, nv
                res%values(k) = real(i, dp) / 3.0_dp + real(k, dp) * 1.0e-7_dp
            end do
            res%values(1) = -huge(1.0_dp) / real(i, dp)
        end select
        select case (mod(i, 5))
        case (0)
            continue                               ! text not allocated
        case (1)
            res%text = ''
        case default
            call add_field(res, 'unit '//int_str(i))
            call add_field(res, repeat(achar(33 + mod(i, 90)), 37 * i))
            if (mod(i, 13) == 4) call add_field(res, repeat('long', 15000))
        end select
        if (mod(i, 3) /= 0) then
            call add_log(res, 'unit '//int_str(i)//': first line')
            do k = 1, mod(i, 4)
                call add_log(res, repeat('-', k)//' line '//int_str(k))
            end do
        end if
    end subroutine make_result

    !> Unit i: a busy wait of 2 ms to 200 ms (units 5, 17, 29, ... are the long ones),
    !> then its result.
    subroutine work(i, res)
        integer, intent(in) :: i
        type(unit_result_t), intent(out) :: res
        integer(int64) :: t0, t, rate, wait
        wait = 2
        if (mod(i, 12) == 5) wait = 200
        call system_clock(t0, rate)
        do
            call system_clock(t)
            if ((t - t0) * 1000 >= wait * rate) exit
        end do
        call make_result(i, res)
        computed = computed + 1
    end subroutine work

    !> On the root: unit i is delivered; compare it with its result rebuilt here.
    subroutine deliver(i, res)
        integer, intent(in) :: i
        type(unit_result_t), intent(in) :: res
        type(unit_result_t) :: ref
        logical :: same
        if (.not. par_root()) then
            call check(.false., 'deliver called on rank '//int_str(par_rank()))
            return
        end if
        if (i < 1 .or. i > NUNIT) then
            call check(.false., 'unit index out of range: '//int_str(i))
            return
        end if
        delivered(i) = delivered(i) + 1
        call make_result(i, ref)
        same = allocated(res%values) .eqv. allocated(ref%values)
        if (same .and. allocated(ref%values)) then
            same = size(res%values) == size(ref%values)
            if (same) same = all(transfer(res%values, 1_int64, size(res%values)) &
                                 == transfer(ref%values, 1_int64, size(ref%values)))
        end if
        call check(same, 'unit '//int_str(i)//': values')
        same = allocated(res%text) .eqv. allocated(ref%text)
        if (same .and. allocated(ref%text)) same = len(res%text) == len(ref%text) &
                                                   .and. res%text == ref%text
        call check(same, 'unit '//int_str(i)//': text')
        same = allocated(res%log) .eqv. allocated(ref%log)
        if (same .and. allocated(ref%log)) same = len(res%log) == len(ref%log) &
                                                  .and. res%log == ref%log
        call check(same, 'unit '//int_str(i)//': log')
    end subroutine deliver

    !> On the root: every unit of todo delivered once, no other.
    subroutine check_delivered(what)
        character(len=*), intent(in) :: what
        integer :: i
        if (.not. par_root()) return
        do i = 1, NUNIT
            if (expected(i)) then
                call check(delivered(i) == 1, what//': unit '//int_str(i)//' delivered ' &
                           //int_str(delivered(i))//' times')
            else
                call check(delivered(i) == 0, what//': unit '//int_str(i)//' (not to do) ' &
                           //'delivered')
            end if
        end do
    end subroutine check_delivered

    !> Count one check (on this rank); a failed one is printed with `what`.
    subroutine check(ok, what)
        logical, intent(in) :: ok
        character(len=*), intent(in) :: what
        if (ok) then
            passed = passed + 1
        else
            failed = failed + 1
            write(output_unit, '(a)') 'FAIL '//what
        end if
    end subroutine check

end module mpi_units_lib

!> The MPI transport of the driver (driver_parallel of parallel_mpi.f90) on synthetic
!> units: `mpirun -n P mpi_units MODE`.
!>
!> Unit i takes a time that differs 100-fold between units (a busy wait) and has a
!> result made from i alone: values of 0 to 100000 numbers, a text of 0 to 60000
!> characters, a log of several lines, each also left unallocated in some units. The root
!> rebuilds every result it is handed and compares it (allocation, sizes, every value
!> bit for bit, every character), and counts that every unit of `todo` is delivered
!> exactly once and no other. Modes:
!>   balance  every rank runs the units (a permutation of a subset of 1..NUNIT); each
!>            worker must have computed some; then a second run on the root alone (the
!>            workers have been told to stop: they return at once).
!>   decline  the workers never run the units: par_finalize declines what the root sends
!>            them, and the root computes those units itself.
!> Without a launcher (one process, MPI not started) the units run as in the serial
!> build. The root prints `N passed, N failed`; the exit status is 1 on a failure.
program mpi_units
    use, intrinsic :: iso_fortran_env, only: output_unit
    use mpi_f08, only: MPI_Gather, MPI_INTEGER, MPI_COMM_WORLD
    use driver_parallel, only: par_init, par_finalize, par_size, par_root, par_mpi_built, &
                               par_run_units
    use seispulse, only: int_str
    use mpi_units_lib, only: NUNIT, delivered, expected, computed, passed, failed, work, &
                             deliver, check_delivered, check
    implicit none

    integer :: k, p
    integer, allocatable :: todo(:), per_rank(:)
    character(len=16) :: mode

    mode = 'balance'
    if (command_argument_count() >= 1) call get_command_argument(1, mode)

    call par_init()
    call check(par_mpi_built(), 'par_mpi_built')
    ! every second unit, from the last down, then the others from the first up
    todo = [(k, k = NUNIT, 1, -2), (k, k = 1, NUNIT - 1, 2)]
    todo = todo(1:NUNIT - 5)
    expected = .false.
    expected(todo) = .true.

    select case (trim(mode))
    case ('balance')
        call par_run_units(todo, work, deliver)
        call check_delivered('balance')
        if (par_size() > 1) then
            ! every worker took part (the root keeps two units assigned to each)
            allocate(per_rank(par_size()))
            call MPI_Gather(computed, 1, MPI_INTEGER, per_rank, 1, MPI_INTEGER, 0, &
                            MPI_COMM_WORLD)
            if (par_root()) then
                do p = 2, par_size()
                    call check(per_rank(p) > 0, 'rank '//int_str(p - 1)//' computed ' &
                               //int_str(per_rank(p))//' units')
                end do
                call check(sum(per_rank) == size(todo), 'units computed over the ranks: ' &
                           //int_str(sum(per_rank)))
            end if
        end if
        ! the workers are stopped: a second run is the root's alone
        delivered = 0
        computed = 0
        todo = [3, 1, 2]
        expected = .false.
        expected(todo) = .true.
        call par_run_units(todo, work, deliver)
        call check_delivered('second run')
        if (.not. par_root()) call check(computed == 0, 'a stopped worker computes nothing')
        if (par_root()) call check(computed == 3, 'the root computes a second run alone')
    case ('decline')
        if (par_root()) then
            call par_run_units(todo, work, deliver)
            call check_delivered('decline')
            call check(computed == size(todo), 'the root computed every unit: ' &
                       //int_str(computed))
        end if
    case default
        call check(.false., 'unknown mode '//trim(mode))
    end select

    call par_finalize()
    if (par_root()) then
        write(output_unit, '(a)') trim(mode)//', '//int_str(par_size())//' rank(s)'
        write(output_unit, '(a)') int_str(passed)//' passed, '//int_str(failed)//' failed'
    end if
    if (failed > 0) error stop 1

end program mpi_units
