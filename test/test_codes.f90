!> Placeholder (issue 7, being written).
module test_codes
    use testing, only: unit_test
    implicit none
    private
    public :: collect_codes
contains
    subroutine collect_codes(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        allocate(tests(0))
    end subroutine collect_codes
end module test_codes
