!> Placeholder (issue 7, being written).
module test_walls_vy
    use testing, only: unit_test
    implicit none
    private
    public :: collect_walls_vy
contains
    subroutine collect_walls_vy(tests)
        type(unit_test), allocatable, intent(out) :: tests(:)
        allocate(tests(0))
    end subroutine collect_walls_vy
end module test_walls_vy
