!> Placeholder (work in progress).
module test_records
    use testing, only: unit_test
    implicit none
    private
    public :: collect_records
contains
    subroutine collect_records(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        allocate(tests(0))
    end subroutine collect_records
end module test_records
