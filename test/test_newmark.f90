!> Placeholder (work in progress).
module test_newmark
    use testing, only: unit_test
    implicit none
    private
    public :: collect_newmark
contains
    subroutine collect_newmark(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        allocate(tests(0))
    end subroutine collect_newmark
end module test_newmark
