!> TEMPORARY STUB (branch c_roll): the rocking_body_t of seispulse_cylinder as agreed, so that
!> seispulse_cylinder_roll builds before the real module is merged; replaced by it at merge.
module seispulse_cylinder
    use seispulse_kinds, only: dp
    implicit none
    private

    public :: rocking_body_t, BODY_SOLID_CYLINDER

    integer, parameter :: BODY_SOLID_CYLINDER = 1   !! solid circular cylinder

    !> A rigid body on a rigid base, rocking in a vertical plane about a point of its base edge.
    type :: rocking_body_t
        integer  :: shape = BODY_SOLID_CYLINDER
        real(dp) :: r = 1.0_dp        !! base radius (m)
        real(dp) :: r_inner = 0.0_dp  !! inner radius of a hollow cylinder (m), else 0
        real(dp) :: h = 1.0_dp        !! height of the centre of mass above the base (m)
        real(dp) :: mass = 1.0_dp     !! kg
        real(dp) :: g = 9.80665_dp    !! m/s^2
        real(dp) :: theta_c = 0.0_dp  !! atan(r/h) (rad)
        real(dp) :: big_r = 0.0_dp    !! sqrt(r^2 + h^2) (m)
        real(dp) :: j_o = 0.0_dp      !! about the pivot, transverse axis (kg m^2)
        real(dp) :: j_g = 0.0_dp      !! about the centre of mass, transverse axis (kg m^2)
        real(dp) :: j_axis = 0.0_dp   !! about the axis of symmetry (kg m^2)
        real(dp) :: p = 0.0_dp        !! sqrt(m g R/J_o) (rad/s)
        real(dp) :: e = 0.0_dp        !! Housner restitution
        real(dp) :: weight = 0.0_dp   !! m g (N)
        real(dp) :: m_max = 0.0_dp    !! m g r (N m)
        real(dp) :: f_uplift = 0.0_dp !! W r/h (N)
    end type rocking_body_t

end module seispulse_cylinder
