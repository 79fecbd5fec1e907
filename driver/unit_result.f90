!> The result of one unit of a batch (one record of a records analysis, with all its
!> rows): what a rank or thread computes and hands to the root, what the restart journal
!> stores, and what the analysis turns into its table rows. An analysis packs its
!> numbers into `values` (integers as exact reals) and its texts into `text` (fields
!> joined by FIELD_SEP); `log` holds the unit's stderr lines (joined by new_line),
!> printed by the root in unit order so that a parallel run says what a serial run says.
module driver_unit_result
    use seispulse, only: dp
    implicit none
    private

    public :: unit_result_t, FIELD_SEP, add_field, get_field, add_log
    public :: unit_work, unit_deliver, run_units_here

    !> Separator of the text fields of a unit (ASCII record separator: never in a
    !> record path, a name or a message the driver writes).
    character(len=1), parameter :: FIELD_SEP = achar(30)

    type :: unit_result_t
        real(dp), allocatable :: values(:)              !! numbers of the unit
        character(len=:), allocatable :: text           !! fields joined by FIELD_SEP
        character(len=:), allocatable :: log            !! stderr lines joined by new_line
    end type unit_result_t

    abstract interface
        !> Compute unit `i` (1-based) into res. Called concurrently from threads (and on
        !> every rank of an MPI job): it must only read shared state.
        subroutine unit_work(i, res)
            import :: unit_result_t
            integer, intent(in) :: i
            type(unit_result_t), intent(out) :: res
        end subroutine unit_work
        !> On the root: unit `i` is done (journal it, keep it, print its log).
        subroutine unit_deliver(i, res)
            import :: unit_result_t
            integer, intent(in) :: i
            type(unit_result_t), intent(in) :: res
        end subroutine unit_deliver
    end interface

contains

    !> The units `todo` in this process: spread over OpenMP threads (dynamic schedule:
    !> records differ in length), each result to `deliver` one at a time (never two
    !> threads at once), in the order the units finish.
    subroutine run_units_here(todo, work, deliver)
        integer, intent(in) :: todo(:)
        procedure(unit_work) :: work
        procedure(unit_deliver) :: deliver
        type(unit_result_t) :: res
        integer :: k
        !$omp parallel do schedule(dynamic, 1) private(res)
        do k = 1, size(todo)
            call work(todo(k), res)
            !$omp critical (seispulse_deliver)
            call deliver(todo(k), res)
            !$omp end critical (seispulse_deliver)
        end do
        !$omp end parallel do
    end subroutine run_units_here

    !> Append one text field.
    subroutine add_field(res, field)
        type(unit_result_t), intent(inout) :: res
        character(len=*), intent(in) :: field
        if (.not. allocated(res%text)) then
            res%text = field
        else
            res%text = res%text//FIELD_SEP//field
        end if
    end subroutine add_field

    !> Text field k (1-based) of res ('' if there is none).
    function get_field(res, k) result(field)
        type(unit_result_t), intent(in) :: res
        integer, intent(in) :: k
        character(len=:), allocatable :: field
        integer :: i, start, stop_
        field = ''
        if (.not. allocated(res%text) .or. k < 1) return
        start = 1
        do i = 1, k - 1
            stop_ = index(res%text(start:), FIELD_SEP)
            if (stop_ == 0) return
            start = start + stop_
        end do
        stop_ = index(res%text(start:), FIELD_SEP)
        if (stop_ == 0) then
            field = res%text(start:)
        else
            field = res%text(start:start + stop_ - 2)
        end if
    end function get_field

    !> Append one stderr line to the unit's log.
    subroutine add_log(res, line)
        type(unit_result_t), intent(inout) :: res
        character(len=*), intent(in) :: line
        if (.not. allocated(res%log)) then
            res%log = line
        else
            res%log = res%log//new_line('a')//line
        end if
    end subroutine add_log

end module driver_unit_result
