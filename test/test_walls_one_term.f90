!> Placeholder (issue 7, being written).
module test_walls_one_term
    use testing, only: unit_test
    implicit none
    private
    public :: collect_walls_one_term
contains
    subroutine collect_walls_one_term(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        allocate(tests(0))
    end subroutine collect_walls_one_term
end module test_walls_one_term
