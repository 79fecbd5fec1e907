! Thin layer of seispulse_cylinder (doc/cylinder.md) for seispulse.cylinder. A body crosses
! the layer as the numbers that define it: its shape code (BODY_*), r (base radius, or the
! half-width b of a block), h, mass, g, r_inner, and J_o, J_axis of a custom body (has_j_axis
! = 0: J_axis unknown). Each wrapper rebuilds it with cylinder_props / block_props, so every
! derived number comes from the library and a body can never be half-updated.

!> The body of a wrapper's arguments (module blocks are helpers, not seen by Python).
module sp_cylinder_body
    use seispulse_kinds, only: dp
    use seispulse_cylinder, only: rocking_body_t, cylinder_props, block_props, BODY_BLOCK, &
                                  BODY_CUSTOM
    implicit none
    private
    public :: make_body

contains

    !> cylinder_props (shape BODY_SOLID_CYLINDER or BODY_HOLLOW_CYLINDER: r_inner decides;
    !> BODY_CUSTOM: with j_o; j_axis when has_j_axis /= 0) or block_props (BODY_BLOCK).
    !> An optional argument not given is an unallocated allocatable: absent (F2008 12.5.2.12).
    subroutine make_body(shape, r, h, mass, g, r_inner, j_o, has_j_axis, j_axis, body, stat, &
                         errmsg)
        integer, intent(in) :: shape, has_j_axis
        real(dp), intent(in) :: r, h, mass, g, r_inner, j_o, j_axis
        type(rocking_body_t), intent(out) :: body
        integer, intent(out) :: stat
        character(len=*), intent(inout) :: errmsg
        real(dp), allocatable :: j_o_opt, j_axis_opt   ! unallocated: absent (F2008)
        if (shape == BODY_BLOCK) then
            call block_props(r, h, mass, g, body, stat, errmsg)
            return
        end if
        if (shape == BODY_CUSTOM) allocate(j_o_opt, source=j_o)
        if (has_j_axis /= 0) allocate(j_axis_opt, source=j_axis)
        call cylinder_props(r, h, mass, g, body, stat, errmsg, r_inner=r_inner, j_o=j_o_opt, &
                            j_axis=j_axis_opt)
    end subroutine make_body

end module sp_cylinder_body

!> Everything of a body: its shape code and derived properties (SI; see rocking_body_t).
subroutine sp_body_props(shape, r, h, mass, g, r_inner, j_o, has_j_axis, j_axis, shape_out, &
                         theta_c, big_r, j_o_out, j_g, j_axis_out, p, e, weight, m_max, &
                         f_uplift, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_cylinder, only: rocking_body_t
    use sp_cylinder_body, only: make_body
    implicit none
    !f2py threadsafe
    integer, intent(in) :: shape, has_j_axis
    real(dp), intent(in) :: r, h, mass, g, r_inner, j_o, j_axis
    integer, intent(out) :: shape_out
    real(dp), intent(out) :: theta_c, big_r, j_o_out, j_g, j_axis_out, p, e, weight, m_max, &
                             f_uplift
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(rocking_body_t) :: body
    errmsg = ''
    call make_body(shape, r, h, mass, g, r_inner, j_o, has_j_axis, j_axis, body, stat, errmsg)
    shape_out = 0
    theta_c = 0.0_dp
    big_r = 0.0_dp
    j_o_out = 0.0_dp
    j_g = 0.0_dp
    j_axis_out = 0.0_dp
    p = 0.0_dp
    e = 0.0_dp
    weight = 0.0_dp
    m_max = 0.0_dp
    f_uplift = 0.0_dp
    if (stat /= SEISPULSE_SUCCESS) return
    shape_out = body%shape
    theta_c = body%theta_c
    big_r = body%big_r
    j_o_out = body%j_o
    j_g = body%j_g
    j_axis_out = body%j_axis
    p = body%p
    e = body%e
    weight = body%weight
    m_max = body%m_max
    f_uplift = body%f_uplift
end subroutine sp_body_props

!> The rocking block (alpha, p, e; g) of a body for seispulse.rocking's integrator, with the
!> restitution e and the linearized flag given.
subroutine sp_body_block(shape, r, h, mass, g, r_inner, j_o, has_j_axis, j_axis, e, linearized, &
                         alpha, p, e_out, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_cylinder, only: rocking_body_t, body_rocking_block
    use seispulse_rocking_sim, only: rocking_block_t
    use sp_cylinder_body, only: make_body
    implicit none
    !f2py threadsafe
    integer, intent(in) :: shape, has_j_axis, linearized
    real(dp), intent(in) :: r, h, mass, g, r_inner, j_o, j_axis, e
    real(dp), intent(out) :: alpha, p, e_out
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(rocking_body_t) :: body
    type(rocking_block_t) :: blk
    errmsg = ''
    alpha = 0.0_dp
    p = 0.0_dp
    e_out = 0.0_dp
    call make_body(shape, r, h, mass, g, r_inner, j_o, has_j_axis, j_axis, body, stat, errmsg)
    if (stat /= SEISPULSE_SUCCESS) return
    call body_rocking_block(body, blk, stat, errmsg, e=e, linearized=linearized /= 0)
    if (stat /= SEISPULSE_SUCCESS) return
    alpha = blk%alpha
    p = blk%p
    e_out = blk%e
end subroutine sp_body_block

!> The solid cylinder with the block's p and M_max (slenderness theta_c when has_theta_c /= 0,
!> else the block's): its r, h (m) and mass (kg).
subroutine sp_equivalent_cylinder(b, h, mass, g, has_theta_c, theta_c, r_c, h_c, mass_c, stat, &
                                  errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_cylinder, only: rocking_body_t, block_props, equivalent_cylinder
    implicit none
    !f2py threadsafe
    integer, intent(in) :: has_theta_c
    real(dp), intent(in) :: b, h, mass, g, theta_c
    real(dp), intent(out) :: r_c, h_c, mass_c
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(rocking_body_t) :: block, cyl
    real(dp), allocatable :: theta_c_opt           ! unallocated: absent (F2008 12.5.2.12)
    errmsg = ''
    r_c = 0.0_dp
    h_c = 0.0_dp
    mass_c = 0.0_dp
    call block_props(b, h, mass, g, block, stat, errmsg)
    if (stat /= SEISPULSE_SUCCESS) return
    if (has_theta_c /= 0) allocate(theta_c_opt, source=theta_c)
    call equivalent_cylinder(block, cyl, stat, errmsg, theta_c=theta_c_opt)
    if (stat /= SEISPULSE_SUCCESS) return
    r_c = cyl%r
    h_c = cyl%h
    mass_c = cyl%mass
end subroutine sp_equivalent_cylinder

!> The uniform block with the body's p and M_max (slenderness alpha when has_alpha /= 0, else
!> the body's theta_c): its half-width b, h (m) and mass (kg).
subroutine sp_equivalent_block(shape, r, h, mass, g, r_inner, j_o, has_j_axis, j_axis, &
                               has_alpha, alpha, b_b, h_b, mass_b, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_cylinder, only: rocking_body_t, equivalent_block
    use sp_cylinder_body, only: make_body
    implicit none
    !f2py threadsafe
    integer, intent(in) :: shape, has_j_axis, has_alpha
    real(dp), intent(in) :: r, h, mass, g, r_inner, j_o, j_axis, alpha
    real(dp), intent(out) :: b_b, h_b, mass_b
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(rocking_body_t) :: cyl, block
    real(dp), allocatable :: alpha_opt             ! unallocated: absent (F2008 12.5.2.12)
    errmsg = ''
    b_b = 0.0_dp
    h_b = 0.0_dp
    mass_b = 0.0_dp
    call make_body(shape, r, h, mass, g, r_inner, j_o, has_j_axis, j_axis, cyl, stat, errmsg)
    if (stat /= SEISPULSE_SUCCESS) return
    if (has_alpha /= 0) allocate(alpha_opt, source=alpha)
    call equivalent_block(cyl, block, stat, errmsg, alpha=alpha_opt)
    if (stat /= SEISPULSE_SUCCESS) return
    b_b = block%r
    h_b = block%h
    mass_b = block%mass
end subroutine sp_equivalent_block

! Hand-written (not in _wrap_loops.txt): rigid_pushover's `stable` is a logical.
!> Static pushover of a solid cylinder (r, h, mass per element; g) at the tilts theta (rad):
!> force (N), moment (N m), stable (1/0), moment/(m g r) and theta/theta_c.
subroutine sp_cyl_rigid_pushover(n, theta, r, h, mass, g, force, moment, stable, m_ratio, u, &
                                 stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_cylinder, only: rocking_body_t, cylinder_props, rigid_pushover
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n
    integer, intent(in) :: n
    real(dp), intent(in) :: theta(n), r(n), h(n), mass(n), g
    real(dp), intent(out) :: force(n), moment(n), m_ratio(n), u(n)
    integer, intent(out) :: stable(n)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(rocking_body_t) :: body
    logical :: st
    integer :: i
    errmsg = ''
    stat = SEISPULSE_SUCCESS
    force = 0.0_dp
    moment = 0.0_dp
    m_ratio = 0.0_dp
    u = 0.0_dp
    stable = 0
    do i = 1, n
        call cylinder_props(r(i), h(i), mass(i), g, body, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call rigid_pushover(body, theta(i), force(i), moment(i), st, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        stable(i) = merge(1, 0, st)
        m_ratio(i) = moment(i) / body%m_max
        u(i) = theta(i) / body%theta_c
    end do
end subroutine sp_cyl_rigid_pushover

!> Overturning map of a body under a pulse family (template packed as in pulse_from_params)
!> on the axes MAP_AXES_*: classes(i, j) for y(i), x(j). e when has_e /= 0.
subroutine sp_body_overturning_map(shape, r, h, mass, g, r_inner, j_o, has_j_axis, j_axis, &
                                   kind, params, axes, linearized, has_e, e, rtol, kv, nx, x, &
                                   ny, y, classes, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_pulses, only: pulse_from_params, PULSE_NPARAM
    use seispulse_cylinder, only: rocking_body_t, body_overturning_map
    use sp_cylinder_body, only: make_body
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: nx, ny
    integer, intent(in) :: shape, has_j_axis, kind, axes, linearized, has_e, nx, ny
    real(dp), intent(in) :: r, h, mass, g, r_inner, j_o, j_axis, params(PULSE_NPARAM), e, rtol
    real(dp), intent(in) :: kv, x(nx), y(ny)
    integer, intent(out) :: classes(ny, nx)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(rocking_body_t) :: body
    real(dp), allocatable :: e_opt                 ! unallocated: absent (F2008 12.5.2.12)
    errmsg = ''
    classes = -1
    call make_body(shape, r, h, mass, g, r_inner, j_o, has_j_axis, j_axis, body, stat, errmsg)
    if (stat /= SEISPULSE_SUCCESS) return
    if (has_e /= 0) allocate(e_opt, source=e)
    call body_overturning_map(body, kind, x, y, axes, classes, stat, errmsg, &
                              template=pulse_from_params(kind, params), &
                              linearized=linearized /= 0, e=e_opt, rtol=rtol, kv=kv)
end subroutine sp_body_overturning_map

!> Cell-by-cell comparison of two class maps of equal shape (MAP_DIFF_* codes).
subroutine sp_map_difference(n1, n2, a, m1, m2, b, diff, stat, errmsg)
    use seispulse_cylinder, only: map_difference
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: n1, n2, m1, m2
    integer, intent(in) :: n1, n2, m1, m2
    integer, intent(in) :: a(n1, n2), b(m1, m2)
    integer, intent(out) :: diff(n1, n2)
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    errmsg = ''
    diff = 0
    call map_difference(a, b, diff, stat, errmsg)
end subroutine sp_map_difference

!> Smallest overturning PGA (g) of a body per pulse frequency freq_hz (Hz), and the uplift
!> threshold (g) it scans from; the optional settings when has_* /= 0.
subroutine sp_body_overturning_threshold(shape, r, h, mass, g, r_inner, j_o, has_j_axis, &
                                         j_axis, kind, params, nf, freq_hz, has_pga_max, &
                                         pga_max_g, has_n_scan, n_scan, has_e, e, linearized, &
                                         rtol, pga_g, uplift_g, stat, errmsg)
    use seispulse_kinds, only: dp
    use seispulse_errors, only: SEISPULSE_SUCCESS
    use seispulse_pulses, only: pulse_t, pulse_from_params, PULSE_NPARAM
    use seispulse_cylinder, only: rocking_body_t, overturning_threshold
    use sp_cylinder_body, only: make_body
    implicit none
    !f2py threadsafe
    !f2py intent(hide) :: nf
    integer, intent(in) :: shape, has_j_axis, kind, nf, has_pga_max, has_n_scan, n_scan, has_e
    integer, intent(in) :: linearized
    real(dp), intent(in) :: r, h, mass, g, r_inner, j_o, j_axis, params(PULSE_NPARAM)
    real(dp), intent(in) :: freq_hz(nf), pga_max_g, e, rtol
    real(dp), intent(out) :: pga_g(nf), uplift_g
    integer, intent(out) :: stat
    character(len=256), intent(out) :: errmsg
    type(rocking_body_t) :: body
    type(pulse_t) :: tpl
    real(dp), allocatable :: pga_max_opt, e_opt    ! unallocated: absent (F2008 12.5.2.12)
    integer, allocatable :: n_scan_opt
    errmsg = ''
    pga_g = 0.0_dp
    uplift_g = 0.0_dp
    call make_body(shape, r, h, mass, g, r_inner, j_o, has_j_axis, j_axis, body, stat, errmsg)
    if (stat /= SEISPULSE_SUCCESS) return
    ! where the scan starts: uplift at |a_g| > g tan(theta_c), g theta_c when linearized
    ! (doc/rocking.md (2.3))
    uplift_g = tan(body%theta_c)
    if (linearized /= 0) uplift_g = body%theta_c
    tpl = pulse_from_params(kind, params)
    if (has_pga_max /= 0) allocate(pga_max_opt, source=pga_max_g)
    if (has_n_scan /= 0) allocate(n_scan_opt, source=n_scan)
    if (has_e /= 0) allocate(e_opt, source=e)
    call overturning_threshold(body, kind, freq_hz, pga_g, stat, errmsg, template=tpl, &
                               pga_max_g=pga_max_opt, n_scan=n_scan_opt, e=e_opt, &
                               linearized=linearized /= 0, rtol=rtol)
end subroutine sp_body_overturning_threshold
