!> Implicit Runge-Kutta integration of stiff systems y' = f(t, y): Radau IIA of order 5
!> (3 stages), the algorithm of Hairer & Wanner's RADAU5 ([HW96] section IV.8), with its
!> error estimate, collocation dense output and event location; doc/rocking.md section 8
!> "Stiff systems: Radau IIA" ((R.12)-(R.19)).
!>
!> The interface is that of `ode_dop853_t` (seispulse_ode), so a model switches with one
!> line; the step-size policy stays with the caller:
!>     call ode%init(n, rtol, atol, stat)
!>     call ode%step(sys, t, y, f, h, t_new, y_new, f_new, err)  ! err <= 1: accept
!>     fac = ode_radau5_factor(err, ode%newton_iters, ode%theta)  ! next h = fac h
!>     call ode%dense_setup(sys, t, y, f, h, y_new, f_new)       ! collocation polynomial
!>     call ode%value(x, yx)                                     ! y(t + x h)
!>     call ode%locate(comp, sgn, level, xa, xb, fa, fb, x, stat)   ! sgn y(comp) = level
!>     call ode%locate_event(sys, i, xa, xb, ga, gb, x, stat)       ! g_i(t, y) = 0
!> A Newton failure (divergence, too slow a contraction, a singular iteration matrix) gives
!> err = huge(1.0_dp): the caller shrinks h (`ode_radau5_factor` gives 0.5) and retries.
!> The system's Jacobian comes from `sys%jacobian` (forward differences unless the model
!> overrides it with its exact Jacobian). `radau5_solve` is a simple adaptive driver.
!>
!> Linear systems: the transformed form of RADAU5 (R.15): one real n x n LU of
!> (gamma/h) I - J and one complex n x n LU of ((alpha + i beta)/h) I - J (LAPACK
!> dgetrf/zgetrf, solves dgetrs/zgetrs through seispulse_lapack), not the 3n x 3n system of
!> the stages: per factorisation 2n^3/3 + 4 (2n^3/3) real operations against 2 (3n)^3/3
!> (n = 4: 213 against 1152), per Newton iteration two solves of size n against one of 3n;
!> for n = 4..8 both are short, but the transformed form is the smaller work, and it is the
!> form whose error estimate (R.17) reuses the real factors.
!>
!> State kept between calls (so that no allocation happens after `init`): the Jacobian
!> and its point, the factors and their h, and the collocation polynomial of the last
!> step. A call that starts at the end of the last step (same t, bit-identical y) takes it
!> as accepted: Newton starts from its polynomial extrapolated (R.16), and its Jacobian is
!> kept when Newton contracted fast (theta <= 0.001); a call from the start of the last
!> step is a retry after a rejection (the Jacobian there is exact and kept); any other call
!> (a new state, e.g. after an impact) starts afresh. A failure with a kept Jacobian is
!> retried once inside `step` with a fresh one.
!>
!> Tolerances: as RADAU5, the given (rtol, atol) are mapped to rtol' = 0.1 rtol^(2/3),
!> atol' = rtol' atol/rtol (the estimate (R.17) is O(h^4) for a method of order 5), and the
!> weights are sc_i = atol'_i + rtol' |y_i| at the start of the step.
module seispulse_radau
    use seispulse_kinds, only: dp, ik
    use seispulse_checks, only: in_open
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, &
                                SEISPULSE_NO_CONVERGENCE, set_error
    use seispulse_lapack, only: lu_factor
    use seispulse_ode, only: ode_system, ode_dense_base, ode_locate, ode_locate_event
    implicit none
    private

    public :: ode_radau5_t, ode_radau5_factor, radau5_solve

    !> Collocation polynomial of the last step (R.18): y(t0 + x h), 0 <= x <= 1, and, as a
    !> function of x for the root finder, sgn y(comp) - level.
    type, extends(ode_dense_base) :: radau_dense_t
        real(dp), allocatable :: y0(:)        !! state at t0, n
        real(dp), allocatable :: y1(:)        !! state at t0 + h, n
        real(dp), allocatable :: c(:, :)      !! divided differences, n x 3
    contains
        procedure :: value => dense_value
        procedure :: component => dense_component
    end type radau_dense_t

    !> Radau IIA (RADAU5) integrator state: tolerances, Jacobian, factors, last step.
    type :: ode_radau5_t
        integer :: n = 0                      !! state dimension
        real(dp) :: rtol = 1.0e-6_dp          !! relative tolerance (as given)
        real(dp), allocatable :: atol(:)      !! absolute tolerances (as given), n
        integer :: newton_iters = 0           !! Newton iterations of the last step
        integer :: n_jac = 0                  !! Jacobian evaluations so far
        integer :: n_lu = 0                   !! factorisations (pairs) so far
        real(dp) :: rtol_i = 0.0_dp           !! internal rtol' (R.17)
        real(dp), allocatable :: atol_i(:)    !! internal atol', n
        real(dp) :: fnewt = 0.0_dp            !! Newton stopping tolerance
        real(dp) :: faccon = 1.0_dp           !! Newton contraction factor kept between steps
        real(dp) :: theta = 1.0_dp            !! contraction rate of the last Newton iteration
        real(dp), allocatable :: jac(:, :)    !! Jacobian, n x n
        real(dp), allocatable :: e1(:, :)     !! LU of (gamma/h) I - J, n x n
        complex(dp), allocatable :: e2(:, :)  !! LU of ((alpha + i beta)/h) I - J, n x n
        complex(dp), allocatable :: zc(:)     !! complex right-hand side, n
        integer(ik), allocatable :: ip1(:), ip2(:)   !! pivots, n
        real(dp), allocatable :: z(:, :)      !! stage increments Z_i = Y_i - y, n x 3
        real(dp), allocatable :: w(:, :)      !! transformed increments W = T^-1 Z, n x 3
        real(dp), allocatable :: fs(:, :)     !! stage derivatives, n x 3
        real(dp), allocatable :: ys(:), scal(:), ee(:), cont(:)   !! work, n
        logical :: have_jac = .false.         !! jac holds J(t_jac, y_jac)
        real(dp) :: t_jac = 0.0_dp
        real(dp), allocatable :: y_jac(:)
        logical :: lu_ok = .false.            !! e1, e2 hold the factors for h_lu and jac
        real(dp) :: h_lu = 0.0_dp
        logical :: have_last = .false.        !! a step was attempted from (t0_last, y0_last)
        logical :: last_ok = .false.          !! ... and converged: its polynomial is cand
        real(dp) :: t0_last = 0.0_dp, t1_last = 0.0_dp, h_last = 0.0_dp
        real(dp), allocatable :: y0_last(:), y1_last(:), cand(:, :)
        logical :: have_prev = .false.        !! polynomial of the step that ended at prev_t1
        real(dp) :: prev_t1 = 0.0_dp, prev_h = 0.0_dp
        real(dp), allocatable :: prev_y1(:), prev(:, :)
        type(radau_dense_t) :: dense          !! dense output of the last step (`dense_setup`)
    contains
        procedure :: init => radau5_init
        procedure :: restart => radau5_restart
        procedure :: step => radau5_step
        procedure :: dense_setup => radau5_dense
        procedure :: value => radau5_value
        procedure :: locate => radau5_locate
        procedure :: locate_event => radau5_locate_event
    end type ode_radau5_t

    ! Radau IIA, s = 3 ([HW96] IV.8, RADAU5): nodes c1, c2, c3 = 1 (R.12); the eigenvalues
    ! gamma = 1/u1 and alpha +- i beta of A^-1 and the transformation T with
    ! T^-1 A^-1 T = [gamma 0 0; 0 alpha -beta; 0 beta alpha] (R.15), T(3, :) = (t31, 1, 0);
    ! the error-estimate weights dd_i = e_i/gamma (R.17).
    real(dp), parameter :: sq6 = 2.449489742783178098197284074705891392_dp
    real(dp), parameter :: c1 = (4.0_dp - sq6) / 10.0_dp, c2 = (4.0_dp + sq6) / 10.0_dp
    real(dp), parameter :: c1m1 = c1 - 1.0_dp, c2m1 = c2 - 1.0_dp, c1mc2 = c1 - c2
    real(dp), parameter :: dd1 = -(13.0_dp + 7.0_dp * sq6) / 3.0_dp
    real(dp), parameter :: dd2 = (-13.0_dp + 7.0_dp * sq6) / 3.0_dp
    real(dp), parameter :: dd3 = -1.0_dp / 3.0_dp
    real(dp), parameter :: gam = 3.637834252744495732208418513577775_dp
    real(dp), parameter :: alph = 2.681082873627752133895790743211112_dp
    real(dp), parameter :: beta = 3.050430199247410569426377624787568_dp
    real(dp), parameter :: t11 = 9.1232394870892942792e-02_dp
    real(dp), parameter :: t12 = -0.14125529502095420843_dp
    real(dp), parameter :: t13 = -3.0029194105147424492e-02_dp
    real(dp), parameter :: t21 = 0.24171793270710701896_dp
    real(dp), parameter :: t22 = 0.20412935229379993199_dp
    real(dp), parameter :: t23 = 0.38294211275726193779_dp
    real(dp), parameter :: t31 = 0.96604818261509293619_dp
    real(dp), parameter :: ti11 = 4.3255798900631553510_dp
    real(dp), parameter :: ti12 = 0.33919925181580986954_dp
    real(dp), parameter :: ti13 = 0.54177053993587487119_dp
    real(dp), parameter :: ti21 = -4.1787185915519047273_dp
    real(dp), parameter :: ti22 = -0.32768282076106238708_dp
    real(dp), parameter :: ti23 = 0.47662355450055045196_dp
    real(dp), parameter :: ti31 = -0.50287263494578687595_dp
    real(dp), parameter :: ti32 = 2.5719269498556054292_dp
    real(dp), parameter :: ti33 = -0.59603920482822492497_dp
    ! RADAU5's defaults: Newton iterations, Jacobian-reuse threshold on theta, safety
    ! factor, step ratio bounds h_new/h in [1/facl, 1/facr], unchanged-h band [1, 1.2].
    integer, parameter :: nit = 7
    real(dp), parameter :: thet = 0.001_dp
    real(dp), parameter :: safe = 0.9_dp
    real(dp), parameter :: facl = 5.0_dp, facr = 0.125_dp
    real(dp), parameter :: quot1 = 1.0_dp, quot2 = 1.2_dp
    real(dp), parameter :: uround = epsilon(1.0_dp)
    !> Shortest step tried: gamma/h and the error weights d_i/h stay finite above it.
    real(dp), parameter :: min_h = 64.0_dp * tiny(1.0_dp)
    !> Newton increments beyond this (in units of the weights) count as divergence (the
    !> next right-hand side would be evaluated far outside any meaningful state).
    real(dp), parameter :: dyno_max = 1.0e30_dp
    !> Newton starts from the last polynomial only for h <= max_ratio times its step (a
    !> cubic extrapolated further is no guess; RADAU5's own steps grow by 8 at most).
    real(dp), parameter :: max_ratio = 10.0_dp

contains

    !> a equals b (bit for bit up to the sign of 0; false for a NaN).
    elemental function same(a, b)
        real(dp), intent(in) :: a, b
        logical :: same
        same = a >= b .and. a <= b
    end function same

    !> Step-size factor h_new/h after a step with error norm err and newton_iters Newton
    !> iterations (RADAU5 [HW96] IV.8, (R.19)): fac = min(0.9, 0.9 (1 + 2 nit)/(newton_iters
    !> + 2 nit)) err^(-1/4) within [0.2, 8], nit = 7; 0.5 after a Newton failure (err = huge);
    !> 0.2 for a NaN err. Given the step's contraction rate theta (`ode%theta`), as RADAU5:
    !> 1 exactly when theta <= 0.001 and fac lies in [1, 1.2] after an accepted step (h
    !> kept: the next step reuses the Jacobian and the factors).
    pure function ode_radau5_factor(err, newton_iters, theta) result(fac)
        real(dp), intent(in) :: err            !! error norm of the step, >= 0, or huge
        integer, intent(in) :: newton_iters    !! Newton iterations of the step (1..7)
        !> Newton contraction rate of the step (dimensionless); absent: the step size is always
        !> changed
        real(dp), intent(in), optional :: theta
        real(dp) :: fac
        real(dp) :: sf
        if (err >= huge(1.0_dp)) then
            fac = 0.5_dp
            return
        else if (.not. err >= 0.0_dp) then
            fac = 1.0_dp / facl
            return
        end if
        sf = min(safe, safe * real(1 + 2 * nit, dp) / real(max(1, newton_iters) + 2 * nit, dp))
        if (err > 0.0_dp) then
            fac = max(facr, min(facl, sqrt(sqrt(err)) / sf))       ! RADAU5's quot
            fac = 1.0_dp / fac
        else
            fac = 1.0_dp / facr
        end if
        if (present(theta)) then
            if (err <= 1.0_dp .and. theta <= thet .and. fac >= quot1 .and. fac <= quot2) &
                fac = 1.0_dp
        end if
    end function ode_radau5_factor

    !> Set up for n states (allocates once; a second call with the same n reuses). The
    !> state between steps is cleared: the next step starts afresh.
    subroutine radau5_init(self, n, rtol, atol, stat, errmsg)
        class(ode_radau5_t), intent(inout) :: self            !! the integrator
        integer, intent(in) :: n                              !! state dimension, >= 1
        real(dp), intent(in) :: rtol                          !! relative tolerance, (10 eps, 1)
        real(dp), intent(in) :: atol(:)                       !! absolute tolerances (n), > 0
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer :: m
        stat = SEISPULSE_SUCCESS
        if (n < 1) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'n: the state dimension ' &
                           //'must be >= 1')
            return
        else if (size(atol) /= n) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'atol: must have n elements')
            return
        else if (.not. in_open(rtol, 10.0_dp * uround, 1.0_dp)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                           'rtol: must be in (10 eps, 1), eps = 2.2e-16')
            return
        end if
        do m = 1, n
            if (.not. in_open(atol(m), 0.0_dp, huge(1.0_dp))) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                               'atol: must be finite and > 0')
                return
            end if
        end do
        if (self%n /= n .or. .not. allocated(self%jac)) then
            if (allocated(self%jac)) deallocate(self%atol, self%atol_i, self%jac, self%e1, &
                self%e2, self%zc, self%ip1, self%ip2, self%z, self%w, self%fs, self%ys, &
                self%scal, self%ee, self%cont, self%y_jac, self%y0_last, self%y1_last, &
                self%cand, self%prev_y1, self%prev, self%dense%y0, self%dense%y1, &
                self%dense%c)
            allocate(self%atol(n), self%atol_i(n), self%jac(n, n), self%e1(n, n), &
                     self%e2(n, n), self%zc(n), self%ip1(n), self%ip2(n), self%z(n, 3), &
                     self%w(n, 3), self%fs(n, 3), self%ys(n), self%scal(n), self%ee(n), &
                     self%cont(n), self%y_jac(n), self%y0_last(n), self%y1_last(n), &
                     self%cand(n, 3), self%prev_y1(n), self%prev(n, 3), self%dense%y0(n), &
                     self%dense%y1(n), self%dense%c(n, 3))
            self%jac = 0.0_dp
            self%e1 = 0.0_dp
            self%e2 = (0.0_dp, 0.0_dp)
            self%zc = (0.0_dp, 0.0_dp)
            self%ip1 = 1
            self%ip2 = 1
            self%z = 0.0_dp
            self%w = 0.0_dp
            self%fs = 0.0_dp
            self%ys = 0.0_dp
            self%scal = 1.0_dp
            self%ee = 0.0_dp
            self%cont = 0.0_dp
            self%y_jac = 0.0_dp
            self%y0_last = 0.0_dp
            self%y1_last = 0.0_dp
            self%cand = 0.0_dp
            self%prev_y1 = 0.0_dp
            self%prev = 0.0_dp
            self%dense%y0 = 0.0_dp
            self%dense%y1 = 0.0_dp
            self%dense%c = 0.0_dp
        end if
        self%n = n
        self%dense%n = n
        self%rtol = rtol
        self%atol(:) = atol
        ! RADAU5's tolerance map (R.17)
        self%rtol_i = 0.1_dp * rtol**(2.0_dp / 3.0_dp)
        self%atol_i(:) = self%rtol_i * (atol / rtol)
        self%fnewt = max(10.0_dp * uround / self%rtol_i, min(0.03_dp, sqrt(self%rtol_i)))
        self%newton_iters = 0
        self%n_jac = 0
        self%n_lu = 0
        call radau5_restart(self)
        if (any(.not. (self%atol_i >= tiny(1.0_dp)))) then
            ! the error weights divide by atol' = rtol' atol/rtol: keep it a normal number
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                           'atol: too small for rtol (rtol'' atol/rtol below the smallest &
                           &normal number)')
            return
        end if
    end subroutine radau5_init

    !> Forget the history (Jacobian, factors, last polynomials, Newton contraction): the
    !> next step starts afresh. A model must call it whenever its right-hand side changes
    !> other than through (t, y) (a contact switch, a new excitation piece with a jump,
    !> parameters changed between steps), because `step` recognises a continuation by a
    !> bit-identical (t, y) alone.
    subroutine radau5_restart(self)
        class(ode_radau5_t), intent(inout) :: self  !! the integrator
        self%faccon = 1.0_dp
        self%theta = 1.0_dp
        self%have_jac = .false.
        self%lu_ok = .false.
        self%have_last = .false.
        self%last_ok = .false.
        self%have_prev = .false.
    end subroutine radau5_restart

    !> One step of size h = t_new - t from (t, y), f = f(t, y): the collocation solution
    !> y_new at t_new, f_new = f(t_new, y_new) and the error norm err (<= 1: accept). A
    !> Newton failure gives err = huge(1.0_dp), y_new = y, f_new = f. The collocation
    !> polynomial stays for `dense_setup`; `newton_iters` holds the iteration count.
    subroutine radau5_step(self, sys, t, y, f, h, t_new, y_new, f_new, err)
        class(ode_radau5_t), intent(inout) :: self  !! the integrator (initialised)
        class(ode_system), intent(inout) :: sys     !! the system
        real(dp), intent(in) :: t                   !! start of the step
        real(dp), contiguous, intent(in) :: y(:)        !! state at t, n
        real(dp), contiguous, intent(in) :: f(:)        !! f(t, y), n
        real(dp), intent(in) :: h                   !! step size, t_new - t
        real(dp), intent(in) :: t_new               !! end of the step
        real(dp), contiguous, intent(out) :: y_new(:)    !! state at t_new, n
        real(dp), contiguous, intent(out) :: f_new(:)    !! f(t_new, y_new), n
        real(dp), intent(out) :: err                !! error norm
        logical :: continuing, start_ok, retry, fresh, converged, ok
        integer :: attempt
        continuing = self%last_ok
        if (continuing) continuing = same(t, self%t1_last) .and. all(same(y, self%y1_last))
        if (continuing) then
            ! the last step was accepted: its polynomial starts the next Newton iteration
            self%prev = self%cand
            self%prev_y1 = self%y1_last
            self%prev_t1 = self%t1_last
            self%prev_h = self%h_last
            self%have_prev = .true.
        end if
        start_ok = self%have_prev
        if (start_ok) start_ok = same(t, self%prev_t1) .and. all(same(y, self%prev_y1))
        retry = self%have_last
        if (retry) retry = same(t, self%t0_last) .and. all(same(y, self%y0_last))
        if (.not. (continuing .or. retry)) then
            ! a new trajectory (e.g. after an impact): RADAU5's first-step Newton
            ! contraction, not the last one's (a fast linear phase would let one
            ! unconverged iteration pass the stop test)
            self%faccon = 1.0_dp
            self%theta = 1.0_dp
        end if
        self%scal = self%atol_i + self%rtol_i * abs(y)
        fresh = .false.
        if (self%have_jac) fresh = same(t, self%t_jac) .and. all(same(y, self%y_jac))
        if (.not. fresh .and. .not. (continuing .and. self%have_jac .and. &
                                     self%theta <= thet)) then
            call new_jacobian(self, sys, t, y, f)
            fresh = .true.
        end if
        self%t0_last = t
        self%y0_last = y
        self%have_last = .true.
        self%last_ok = .false.
        converged = .false.
        self%newton_iters = 0
        if (abs(h) >= min_h .and. abs(h) < huge(1.0_dp)) then
            do attempt = 1, 2
                ok = .true.
                if (.not. (self%lu_ok .and. same(h, self%h_lu))) call decompose(self, h, ok)
                if (ok) call newton(self, sys, t, y, h, t_new, &
                                    start_ok .and. abs(h) <= max_ratio * abs(self%prev_h), &
                                    converged)
                if (converged .or. fresh) exit
                call new_jacobian(self, sys, t, y, f)   ! a kept Jacobian: retry with J(t, y)
                fresh = .true.
            end do
        end if
        if (.not. converged) then
            self%theta = 1.0_dp
            err = huge(1.0_dp)
            y_new = y
            f_new = f
            return
        end if
        y_new = y + self%z(:, 3)
        call sys%rhs(t_new, y_new, f_new)
        call estimate(self, sys, t, y, f, h, retry .or. .not. start_ok, err)
        call collocation(self%z, self%cand)
        self%t1_last = t_new
        self%y1_last = y_new
        self%h_last = h
        self%last_ok = .true.
    end subroutine radau5_step

    !> J = df/dy at (t, y) from the system; the factors are then out of date.
    subroutine new_jacobian(self, sys, t, y, f)
        type(ode_radau5_t), intent(inout) :: self
        class(ode_system), intent(inout) :: sys
        real(dp), intent(in) :: t
        real(dp), contiguous, intent(in) :: y(:), f(:)
        call sys%jacobian(t, y, f, self%jac)
        self%n_jac = self%n_jac + 1
        self%have_jac = .true.
        self%t_jac = t
        self%y_jac = y
        self%lu_ok = .false.
    end subroutine new_jacobian

    !> Factors of E1 = (gamma/h) I - J (real) and E2 = ((alpha + i beta)/h) I - J
    !> (complex) (R.15); ok = .false. if one is singular.
    subroutine decompose(self, h, ok)
        type(ode_radau5_t), intent(inout) :: self
        real(dp), intent(in) :: h
        logical, intent(out) :: ok
        integer :: m, stat
        self%e1 = -self%jac
        self%e2 = cmplx(-self%jac, 0.0_dp, kind=dp)
        do m = 1, self%n
            self%e1(m, m) = self%e1(m, m) + gam / h
            self%e2(m, m) = self%e2(m, m) + cmplx(alph / h, beta / h, kind=dp)
        end do
        self%n_lu = self%n_lu + 1
        self%lu_ok = .false.
        call lu_factor(self%e1, self%ip1, stat)
        ok = stat == SEISPULSE_SUCCESS
        if (.not. ok) return
        call lu_factor(self%e2, self%ip2, stat)
        ok = stat == SEISPULSE_SUCCESS
        if (.not. ok) return
        self%lu_ok = .true.
        self%h_lu = h
    end subroutine decompose

    !> Simplified Newton iteration for the stage increments Z (R.14)-(R.16): starting values
    !> from the previous step's polynomial (or 0), convergence monitored by the contraction
    !> rate theta; converged = .false. on divergence (theta >= 0.99), on a predicted miss of
    !> the tolerance within nit iterations, or after nit iterations.
    subroutine newton(self, sys, t, y, h, t_new, start_ok, converged)
        type(ode_radau5_t), intent(inout) :: self
        class(ode_system), intent(inout) :: sys
        real(dp), intent(in) :: t, h, t_new
        real(dp), contiguous, intent(in) :: y(:)
        logical, intent(in) :: start_ok
        logical, intent(out) :: converged
        real(dp) :: c3q, c1q, c2q, fac1, alphn, betan, dyno, dynold, thq, thqold, theta, dyth
        real(dp) :: a1, a2, a3
        integer :: n, m, newt
        n = self%n
        converged = .false.
        associate(z => self%z, w => self%w, fs => self%fs, ys => self%ys, scal => self%scal)
            if (start_ok) then
                ! (R.16): the last polynomial at t + c_i h
                c3q = h / self%prev_h
                c1q = c1 * c3q
                c2q = c2 * c3q
                do m = 1, n
                    associate(ak1 => self%prev(m, 1), ak2 => self%prev(m, 2), &
                              ak3 => self%prev(m, 3))
                        z(m, 1) = c1q * (ak1 + (c1q - c2m1) * (ak2 + (c1q - c1m1) * ak3))
                        z(m, 2) = c2q * (ak1 + (c2q - c2m1) * (ak2 + (c2q - c1m1) * ak3))
                        z(m, 3) = c3q * (ak1 + (c3q - c2m1) * (ak2 + (c3q - c1m1) * ak3))
                    end associate
                    w(m, 1) = ti11 * z(m, 1) + ti12 * z(m, 2) + ti13 * z(m, 3)
                    w(m, 2) = ti21 * z(m, 1) + ti22 * z(m, 2) + ti23 * z(m, 3)
                    w(m, 3) = ti31 * z(m, 1) + ti32 * z(m, 2) + ti33 * z(m, 3)
                end do
            else
                z = 0.0_dp
                w = 0.0_dp
            end if
            fac1 = gam / h
            alphn = alph / h
            betan = beta / h
            self%faccon = max(self%faccon, uround)**0.8_dp
            theta = thet
            dynold = 1.0_dp
            thqold = 1.0_dp
            newt = 0
            do
                if (newt >= nit) exit
                ys = y + z(:, 1)
                call sys%rhs(t + c1 * h, ys, fs(:, 1))
                ys = y + z(:, 2)
                call sys%rhs(t + c2 * h, ys, fs(:, 2))
                ys = y + z(:, 3)
                call sys%rhs(t_new, ys, fs(:, 3))
                ! (R.15): T^-1 F - (Lambda/h) W, then the two solves
                do m = 1, n
                    a1 = fs(m, 1)
                    a2 = fs(m, 2)
                    a3 = fs(m, 3)
                    z(m, 1) = ti11 * a1 + ti12 * a2 + ti13 * a3 - fac1 * w(m, 1)
                    z(m, 2) = ti21 * a1 + ti22 * a2 + ti23 * a3 - alphn * w(m, 2) &
                        + betan * w(m, 3)
                    z(m, 3) = ti31 * a1 + ti32 * a2 + ti33 * a3 - alphn * w(m, 3) &
                        - betan * w(m, 2)
                    self%zc(m) = cmplx(z(m, 2), z(m, 3), kind=dp)
                end do
                call solve_real(self%e1, self%ip1, z(:, 1))
                call solve_complex(self%e2, self%ip2, self%zc)
                z(:, 2) = real(self%zc, dp)
                z(:, 3) = aimag(self%zc)
                newt = newt + 1
                dyno = 0.0_dp
                do m = 1, n
                    dyno = dyno + (z(m, 1) / scal(m))**2 + (z(m, 2) / scal(m))**2 &
                        + (z(m, 3) / scal(m))**2
                end do
                dyno = sqrt(dyno / real(3 * n, dp))
                if (.not. dyno <= dyno_max) exit            ! NaN or runaway: failure
                if (newt > 1 .and. newt < nit) then
                    thq = dyno / dynold
                    if (newt == 2) then
                        theta = thq
                    else
                        theta = sqrt(thq * thqold)
                    end if
                    thqold = thq
                    if (.not. theta < 0.99_dp) exit          ! divergence
                    self%faccon = theta / (1.0_dp - theta)
                    dyth = self%faccon * dyno * theta**(nit - 1 - newt) / self%fnewt
                    if (dyth >= 1.0_dp) exit                 ! will not converge in time
                end if
                dynold = max(dyno, uround)
                do m = 1, n
                    w(m, 1) = w(m, 1) + z(m, 1)
                    w(m, 2) = w(m, 2) + z(m, 2)
                    w(m, 3) = w(m, 3) + z(m, 3)
                    z(m, 1) = t11 * w(m, 1) + t12 * w(m, 2) + t13 * w(m, 3)
                    z(m, 2) = t21 * w(m, 1) + t22 * w(m, 2) + t23 * w(m, 3)
                    z(m, 3) = t31 * w(m, 1) + w(m, 2)
                end do
                if (self%faccon * dyno <= self%fnewt) then
                    converged = .true.
                    exit
                end if
            end do
        end associate
        self%theta = theta
        self%newton_iters = newt
    end subroutine newton

    !> x = A^-1 b in place from dgetrf's factors: the row interchanges, then the unit
    !> lower and the upper triangle, in the operation order of dgetrs (dlaswp, dtrsm; the
    !> same values up to the sign of a zero); written out because for n = 4..8 the calls through dgetrs
    !> (argument checks, dtrsm's case selection) cost more than the 2 n^2 operations.
    pure subroutine solve_real(lu, ip, b)
        real(dp), intent(in) :: lu(:, :)
        integer(ik), intent(in) :: ip(:)
        real(dp), intent(inout) :: b(:)
        real(dp) :: tmp
        integer :: i, k, n
        n = size(b)
        do k = 1, n
            i = int(ip(k))
            if (i /= k) then
                tmp = b(k)
                b(k) = b(i)
                b(i) = tmp
            end if
        end do
        do k = 1, n
            do i = k + 1, n
                b(i) = b(i) - b(k) * lu(i, k)
            end do
        end do
        do k = n, 1, -1
            b(k) = b(k) / lu(k, k)
            do i = 1, k - 1
                b(i) = b(i) - b(k) * lu(i, k)
            end do
        end do
    end subroutine solve_real

    !> The same from zgetrf's factors (zgetrs).
    pure subroutine solve_complex(lu, ip, b)
        complex(dp), intent(in) :: lu(:, :)
        integer(ik), intent(in) :: ip(:)
        complex(dp), intent(inout) :: b(:)
        complex(dp) :: tmp
        integer :: i, k, n
        n = size(b)
        do k = 1, n
            i = int(ip(k))
            if (i /= k) then
                tmp = b(k)
                b(k) = b(i)
                b(i) = tmp
            end if
        end do
        do k = 1, n
            do i = k + 1, n
                b(i) = b(i) - b(k) * lu(i, k)
            end do
        end do
        do k = n, 1, -1
            b(k) = b(k) / lu(k, k)
            do i = 1, k - 1
                b(i) = b(i) - b(k) * lu(i, k)
            end do
        end do
    end subroutine solve_complex

    !> RADAU5's error estimate (R.17): err = || E1^-1 (f(t, y) + (dd . Z)/h) || in the
    !> weights; when it exceeds 1 on a first step or a retry, once more with
    !> f(t, y + err) in place of f(t, y) (the refinement for very stiff components).
    subroutine estimate(self, sys, t, y, f, h, refine, err)
        type(ode_radau5_t), intent(inout) :: self
        class(ode_system), intent(inout) :: sys
        real(dp), intent(in) :: t, h
        real(dp), contiguous, intent(in) :: y(:), f(:)
        logical, intent(in) :: refine
        real(dp), intent(out) :: err
        real(dp) :: hee1, hee2, hee3
        hee1 = dd1 / h
        hee2 = dd2 / h
        hee3 = dd3 / h
        associate(z => self%z, ee => self%ee, cont => self%cont)
            ee = hee1 * z(:, 1) + hee2 * z(:, 2) + hee3 * z(:, 3)
            cont = ee + f
            call solve_real(self%e1, self%ip1, cont)
            err = max(sqrt(sum((cont / self%scal)**2) / real(self%n, dp)), 1.0e-10_dp)
            if (err > 1.0_dp .and. refine .and. err < huge(1.0_dp)) then
                self%ys = y + cont
                call sys%rhs(t, self%ys, self%fs(:, 1))
                cont = self%fs(:, 1) + ee
                call solve_real(self%e1, self%ip1, cont)
                err = max(sqrt(sum((cont / self%scal)**2) / real(self%n, dp)), 1.0e-10_dp)
            end if
        end associate
        if (.not. err < huge(1.0_dp)) err = huge(1.0_dp)
    end subroutine estimate

    !> Divided differences of the collocation polynomial through y (x = 0), y + Z1,
    !> y + Z2, y + Z3 (x = c1, c2, 1) in RADAU5's form (R.18).
    pure subroutine collocation(z, c)
        real(dp), intent(in) :: z(:, :)
        real(dp), intent(out) :: c(:, :)
        integer :: m
        real(dp) :: ak, acont3
        do m = 1, size(z, 1)
            c(m, 1) = (z(m, 2) - z(m, 3)) / c2m1
            ak = (z(m, 1) - z(m, 2)) / c1mc2
            acont3 = (ak - z(m, 1) / c1) / c2
            c(m, 2) = (ak - c(m, 1)) / c1m1
            c(m, 3) = c(m, 2) - acont3
        end do
    end subroutine collocation

    !> Dense output of the step just taken by `step` (same arguments): its collocation
    !> polynomial (R.18), of local order 4 in the interior (exact at both ends). For a step
    !> that is not the last one `step` computed (or that failed), the cubic Hermite
    !> interpolant of (y, f, y_new, f_new), of the same order.
    subroutine radau5_dense(self, sys, t, y, f, h, y_new, f_new)
        class(ode_radau5_t), intent(inout) :: self  !! the integrator, after `step`
        class(ode_system), intent(inout) :: sys     !! the system (not used)
        real(dp), intent(in) :: t                   !! start of the step
        real(dp), contiguous, intent(in) :: y(:)        !! state at t, n
        real(dp), contiguous, intent(in) :: f(:)        !! f(t, y), n
        real(dp), intent(in) :: h                   !! step size
        real(dp), contiguous, intent(in) :: y_new(:)     !! state at t + h, n
        real(dp), contiguous, intent(in) :: f_new(:)     !! f there, n
        real(dp), parameter :: nodes(3) = [c1, c2, 1.0_dp]
        real(dp) :: b01, b10, b11, x
        integer :: i
        associate(unused => sys)
        end associate
        if (self%last_ok .and. same(t, self%t0_last) .and. same(h, self%h_last) .and. &
            all(same(y_new, self%y1_last)) .and. all(same(y, self%y0_last))) then
            self%dense%c = self%cand
        else
            ! Hermite values at x = c1, c2, 1 as increments Z, then the same form
            do i = 1, 3
                x = nodes(i)
                b01 = x**2 * (3.0_dp - 2.0_dp * x)
                b10 = x * (1.0_dp - x)**2
                b11 = x**2 * (x - 1.0_dp)
                self%z(:, i) = b01 * (y_new - y) + (b10 * h) * f + (b11 * h) * f_new
            end do
            call collocation(self%z, self%dense%c)
        end if
        self%dense%y0 = y
        self%dense%y1 = y_new
        self%dense%t0 = t
        self%dense%h = h
    end subroutine radau5_dense

    !> Dense output y(t0 + x h) of the last step (after `dense_setup`).
    subroutine radau5_value(self, x, y)
        class(ode_radau5_t), intent(in) :: self  !! the integrator
        real(dp), intent(in) :: x                !! fraction of the step, [0, 1]
        real(dp), intent(out) :: y(:)            !! state, n
        call self%dense%value(x, y)
    end subroutine radau5_value

    !> Root x in [xa, xb] of sgn y(comp)(x) - level on the dense output, given its values
    !> fa, fb at the ends (of opposite signs, or one of them 0); x = xa if xb <= xa.
    subroutine radau5_locate(self, comp, sgn, level, xa, xb, fa, fb, x, stat, errmsg)
        class(ode_radau5_t), intent(inout) :: self            !! the integrator
        integer, intent(in) :: comp                           !! component, 1..n
        real(dp), intent(in) :: sgn                           !! its sign factor
        real(dp), intent(in) :: level                         !! level crossed
        real(dp), intent(in) :: xa                            !! bracket start (fraction)
        real(dp), intent(in) :: xb                            !! bracket end (fraction)
        real(dp), intent(in) :: fa                            !! sgn y(comp) - level at xa
        real(dp), intent(in) :: fb                            !! same at xb
        real(dp), intent(out) :: x                            !! the root, in [xa, xb]
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        call ode_locate(self%dense, comp, sgn, level, xa, xb, fa, fb, x, stat, errmsg)
    end subroutine radau5_locate

    !> Root x in [xa, xb] of the system's event function g_i(t0 + x h, y(x)) on the
    !> dense output, given ga, gb at the ends (of opposite signs, or one of them 0).
    subroutine radau5_locate_event(self, sys, i, xa, xb, ga, gb, x, stat, errmsg)
        class(ode_radau5_t), intent(inout), target :: self    !! the integrator
        class(ode_system), intent(inout), target :: sys       !! the system
        integer, intent(in) :: i                              !! event number
        real(dp), intent(in) :: xa                            !! bracket start (fraction)
        real(dp), intent(in) :: xb                            !! bracket end (fraction)
        real(dp), intent(in) :: ga                            !! g_i at xa
        real(dp), intent(in) :: gb                            !! g_i at xb
        real(dp), intent(out) :: x                            !! the root, in [xa, xb]
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        call ode_locate_event(self%dense, sys, i, xa, xb, ga, gb, x, stat, errmsg)
    end subroutine radau5_locate_event

    !> y(t0 + x h) = y1 + s (c1 + (s - c2 + 1) (c2 + (s - c1 + 1) c3)), s = x - 1 (R.18);
    !> y0 and y1 exactly at x = 0 and 1.
    pure subroutine dense_value(self, x, y)
        class(radau_dense_t), intent(in) :: self  !! the dense output
        real(dp), intent(in) :: x                 !! fraction of the step
        real(dp), intent(out) :: y(:)             !! state, n
        real(dp) :: s
        if (same(x, 0.0_dp)) then
            y = self%y0
            return
        end if
        s = x - 1.0_dp
        y = self%y1 + s * (self%c(:, 1) + (s - c2m1) * (self%c(:, 2) + (s - c1m1) &
                                                        * self%c(:, 3)))
    end subroutine dense_value

    !> Component m of y(t0 + x h).
    pure function dense_component(self, m, x) result(v)
        class(radau_dense_t), intent(in) :: self  !! the dense output
        integer, intent(in) :: m                  !! component, 1..n
        real(dp), intent(in) :: x                 !! fraction of the step
        real(dp) :: v
        real(dp) :: s
        if (same(x, 0.0_dp)) then
            v = self%y0(m)
            return
        end if
        s = x - 1.0_dp
        v = self%y1(m) + s * (self%c(m, 1) + (s - c2m1) * (self%c(m, 2) + (s - c1m1) &
                                                           * self%c(m, 3)))
    end function dense_component

    !> Integrate y' = f(t, y) from t0 to t1 (either direction) with adaptive steps: the
    !> initial step of [HNW93] II.4, the factor `ode_radau5_factor` (no growth right after
    !> a rejection, 0.1 after a rejected first step), at most 100000 step attempts. y holds
    !> y(t0) on entry and y(t1) on return (the last state reached if stat /= 0).
    subroutine radau5_solve(sys, t0, t1, y, rtol, atol, stat, errmsg, n_steps)
        class(ode_system), intent(inout) :: sys               !! the system
        real(dp), intent(in) :: t0                            !! start time
        real(dp), intent(in) :: t1                            !! end time
        real(dp), contiguous, intent(inout) :: y(:)           !! state, n: y(t0) in, y(t1) out
        real(dp), intent(in) :: rtol                          !! relative tolerance, (10 eps, 1)
        real(dp), intent(in) :: atol(:)                       !! absolute tolerance(s) > 0: 1 or n
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        integer, intent(out), optional :: n_steps             !! accepted steps
        integer, parameter :: max_attempts = 100000
        type(ode_radau5_t) :: ode
        real(dp), allocatable :: f(:), y_new(:), f_new(:), atol_v(:)
        real(dp) :: t, h, t_new, err, fac, span
        integer :: n, steps, attempts
        logical :: first, rejected
        n = size(y)
        steps = 0
        if (present(n_steps)) n_steps = 0
        stat = SEISPULSE_SUCCESS
        if (.not. (abs(t0) < huge(1.0_dp) .and. abs(t1) < huge(1.0_dp))) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 't0, t1: must be finite')
            return
        else if (size(atol) /= 1 .and. size(atol) /= n) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, &
                           'atol: must have 1 or n elements')
            return
        end if
        allocate(atol_v(n))
        if (size(atol) == 1) then
            atol_v = atol(1)
        else
            atol_v = atol
        end if
        call ode%init(n, rtol, atol_v, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        span = t1 - t0
        if (same(span, 0.0_dp)) return
        allocate(f(n), y_new(n), f_new(n))
        call sys%rhs(t0, y, f)
        h = initial_step(sys, t0, y, f, span, rtol, atol_v, y_new, f_new)
        t = t0
        first = .true.
        rejected = .false.
        do attempts = 1, max_attempts
            if (abs(t + h - t0) >= abs(span)) then
                t_new = t1
                h = t1 - t
            else
                t_new = t + h
            end if
            call ode%step(sys, t, y, f, h, t_new, y_new, f_new, err)
            fac = ode_radau5_factor(err, ode%newton_iters, ode%theta)
            if (err <= 1.0_dp) then
                t = t_new
                y = y_new
                f = f_new
                steps = steps + 1
                if (present(n_steps)) n_steps = steps
                if (same(t, t1)) return
                if (rejected) fac = min(fac, 1.0_dp)
                first = .false.
                rejected = .false.
            else
                if (first .and. err < huge(1.0_dp)) fac = 0.1_dp
                rejected = .true.
            end if
            h = h * fac
            if (.not. (abs(h) > 10.0_dp * uround * abs(t) .and. abs(h) > tiny(1.0_dp))) then
                call set_error(stat, errmsg, SEISPULSE_NO_CONVERGENCE, &
                               't1: the step size fell below the resolution of t')
                return
            end if
        end do
        call set_error(stat, errmsg, SEISPULSE_NO_CONVERGENCE, &
                       't1: not reached within 100000 step attempts')
    end subroutine radau5_solve

    !> Initial step ([HNW93] II.4, order 5): from ||y||, ||f|| and a difference quotient of
    !> f along an explicit Euler step, in the weights atol + rtol |y|; signed as span.
    function initial_step(sys, t0, y, f, span, rtol, atol, y1, f1) result(h)
        class(ode_system), intent(inout) :: sys
        real(dp), intent(in) :: t0, span, rtol
        real(dp), contiguous, intent(in) :: y(:), f(:), atol(:)
        real(dp), contiguous, intent(inout) :: y1(:), f1(:)
        real(dp) :: h
        real(dp) :: d0, d1, d2, h0, h1
        integer :: n
        n = size(y)
        d0 = sqrt(sum((y / (atol + rtol * abs(y)))**2) / real(n, dp))
        d1 = sqrt(sum((f / (atol + rtol * abs(y)))**2) / real(n, dp))
        if (d0 < 1.0e-5_dp .or. d1 < 1.0e-5_dp) then
            h0 = 1.0e-6_dp
        else
            h0 = 0.01_dp * d0 / d1
        end if
        h0 = min(h0, abs(span))
        y1 = y + sign(h0, span) * f
        call sys%rhs(t0 + sign(h0, span), y1, f1)
        d2 = sqrt(sum(((f1 - f) / (atol + rtol * abs(y)))**2) / real(n, dp)) / h0
        if (max(d1, d2) <= 1.0e-15_dp) then
            h1 = max(1.0e-6_dp, h0 * 1.0e-3_dp)
        else
            h1 = (0.01_dp / max(d1, d2))**(1.0_dp / 6.0_dp)
        end if
        h = sign(min(100.0_dp * h0, h1, abs(span)), span)
    end function initial_step

end module seispulse_radau
