!> Placeholder suite (issue 6).
module test_sdof
    use testing, only: unit_test, new_unittest, test_error
    implicit none
    private
    public :: collect_sdof
contains
    subroutine collect_sdof(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        tests = [new_unittest('placeholder', placeholder)]
    end subroutine collect_sdof
    subroutine placeholder(error)
        type(test_error), allocatable, intent(out) :: error
    end subroutine placeholder
end module test_sdof
