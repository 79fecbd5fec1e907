!> Event-driven stick-slip integrator for a rigid block on a frictional plane
!> (Newmark sliding block): the reference that checks the closed forms of
!> doc/sliding.md, and the tool for real accelerograms.
!>
!> Relative (sliding) displacement u of the block with respect to the plane
!> (doc/sliding.md section 1, Eq. 1.3, with the stick-slip law written out there):
!>     u'' = a_g(t) - ay_dir sgn(u')          while sliding,
!>     u'  = 0                                while at rest and -thr_rev <= a_g <= thr_fwd.
!> Onset from rest: forward when a_g > thr_fwd, reverse when a_g < -thr_rev, where
!> thr_dir = static_factor ay_dir for the first onset of the run (and for every
!> onset if `static_all`), else ay_dir (doc/sliding.md section 8). While sliding the kinetic
!> ay_dir applies. When a slide stops at t_s and a_g(t_s) already exceeds the
!> threshold the other way, the block reverses at once ("slip", doc/sliding.md section 5);
!> otherwise it sticks until the next onset.
!>
!> Method: exact events, no time step (doc/sliding.md section 9). The time axis is cut into
!> pieces on which a_g is continuous and monotone (seispulse_pieces, shared with the
!> rocking integrator of seispulse_rocking_sim). On such a piece a_g - thr has at
!> most one root (the onset), u'' = a_g - s ay changes sign at most once (the piece
!> is split there), and on each part u' is monotone, so a stop is bracketed by a
!> sign check at the ends. Every event is located by Brent's method (seispulse_roots)
!> to full double precision. The relative motion on a piece is propagated from a
!> reference state (t_r, u_r, w_r) set at the piece start and at each event:
!>     w(t) = w_r + [v_g(t) - v_g(t_r)] - s ay (t - t_r)
!>     u(t) = u_r + w_r (t - t_r) + [d_g(t) - d_g(t_r) - v_g(t_r)(t - t_r)] - s ay (t - t_r)^2/2
!> (doc/sliding.md section 2, Eqs. 1.4-1.5), with the closed-form v_g, d_g of a pulse, or the
!> local polynomial of a record step (never the cumulative ground velocity).
!> The peak sliding velocity is where a_g = s ay (the split points) or at a piece end.
!> After the excitation (a_g = 0) a sliding block stops at t + |w|/ay exactly.
!>
!> Conventions of the result: a slide of zero length (the threshold touched but not
!> exceeded, by more than two ulps) is not reported; `t_end` is the stop of the last
!> slide (0 if the block never slides). Optional output grid: `t_grid`, `u_grid`,
!> `w_grid` all present or all absent, of one size, `t_grid` finite and ascending
!> (any times: u = 0 before the first onset, u = u_final and u' = 0 after `t_end`);
!> values come from the same closed forms as the events, not from interpolation.
module seispulse_sliding_sim
    use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf
    use seispulse_kinds, only: dp
    use seispulse_checks, only: positive, finite_at_least, check_output_grid
    use seispulse_errors, only: SEISPULSE_SUCCESS, SEISPULSE_INVALID_INPUT, SEISPULSE_INTERNAL, &
                                set_error
    use seispulse_format, only: real_str
    use seispulse_roots, only: scalar_function, find_root
    use seispulse_pulses, only: pulse_t, pulse_validate, pulse_at, exp_consts_t, exp_consts, &
                                PULSE_EXPONENTIAL
    use seispulse_pieces, only: piece_t, piece_iter_t, pulse_pieces_check, record_step_check, &
                                record_in_si, g_product_max, pulse_pieces_init, &
                                record_pieces_init, next_piece, exceeds, onset_on_piece
    implicit none
    private

    public :: friction_t, slide_t, stickslip_result_t
    public :: friction_validate, stickslip_pulse, stickslip_record

    !> Friction of the block, as yield accelerations in the units of the ground
    !> acceleration: the pulse's for `stickslip_pulse` (A_g units for the dimensionless
    !> problem: ay = eta), g for `stickslip_record` (like the record).
    type :: friction_t
        real(dp) :: ay_fwd = 0.1_dp         !! resistance to forward (u' > 0) sliding, > 0, or +inf
        real(dp) :: ay_rev = 0.1_dp         !! resistance to reverse sliding, > 0, or +inf
        real(dp) :: static_factor = 1.0_dp  !! onset threshold / kinetic resistance, >= 1, finite
        logical :: static_all = .false.     !! static threshold at every onset, not only the first
    end type friction_t

    !> One sliding interval.
    type :: slide_t
        integer :: direction = 0            !! +1 forward, -1 reverse
        real(dp) :: t_start = 0.0_dp        !! onset time
        real(dp) :: t_stop = 0.0_dp         !! stop time (u' = 0 again)
        real(dp) :: u_start = 0.0_dp        !! relative displacement at onset
        real(dp) :: u_stop = 0.0_dp         !! relative displacement at the stop
        real(dp) :: w_peak = 0.0_dp         !! largest |u'| in the interval
        real(dp) :: t_peak = 0.0_dp         !! time of w_peak
        logical :: from_slip = .false.      !! started by an immediate reversal at the previous stop
    end type slide_t

    !> Result of a run.
    type :: stickslip_result_t
        type(slide_t), allocatable :: slides(:)  !! the slides in time order
        real(dp) :: u_final = 0.0_dp        !! u when the block is finally at rest
        real(dp) :: u_max = 0.0_dp          !! largest u over the run (>= 0)
        real(dp) :: u_min = 0.0_dp          !! smallest u over the run (<= 0)
        real(dp) :: t_end = 0.0_dp          !! stop of the last slide (0 if none)
    end type stickslip_result_t

    integer, parameter :: SRC_PULSE = 1, SRC_RECORD = 2
    integer, parameter :: EVAL_ACCEL = 1, EVAL_VELOCITY = 2

    !> Events allowed on one monotone piece; a handful are possible (onset, split,
    !> stop, reverse onset, ...), so reaching this is a bug, reported as such.
    integer, parameter :: max_events = 64

    !> Ground acceleration and relative velocity on the current piece, as a function
    !> for the root finder (the components carry the piece and the reference state).
    type, extends(scalar_function) :: ground_fn
        integer :: src = SRC_PULSE
        integer :: what = EVAL_ACCEL       !! EVAL_ACCEL: a_g - level; EVAL_VELOCITY: w
        type(pulse_t) :: p                 !! the pulse (SRC_PULSE)
        type(exp_consts_t) :: cexp         !! its beta constants (exponential kind)
        real(dp) :: level = 0.0_dp         !! subtracted from a_g (EVAL_ACCEL)
        real(dp) :: t0 = 0.0_dp            !! record step: start time
        real(dp) :: a0 = 0.0_dp            !! record step: a_g at t0
        real(dp) :: slope = 0.0_dp         !! record step: da_g/dt
        real(dp) :: t_ref = 0.0_dp         !! reference state of the relative motion
        real(dp) :: u_ref = 0.0_dp
        real(dp) :: w_ref = 0.0_dp
        real(dp) :: v_ref = 0.0_dp         !! pulse: v_g(t_ref)
        real(dp) :: d_ref = 0.0_dp         !! pulse: d_g(t_ref)
        real(dp) :: a_ref = 0.0_dp         !! record: a_g(t_ref)
        real(dp) :: c = 0.0_dp             !! s ay of the current slide
    contains
        procedure :: eval => ground_eval
    end type ground_fn

contains

    ! ------------------------------------------------------------------------------
    ! Public API
    ! ------------------------------------------------------------------------------

    !> Check friction parameters; the message names the offending parameter.
    subroutine friction_validate(fr, stat, errmsg)
        type(friction_t), intent(in) :: fr                    !! the friction
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        stat = SEISPULSE_SUCCESS
        if (.not. positive(fr%ay_fwd)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ay_fwd = ' &
                           //real_str(fr%ay_fwd)//': must be > 0 (or +inf for no sliding that way)')
        else if (.not. positive(fr%ay_rev)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ay_rev = ' &
                           //real_str(fr%ay_rev)//': must be > 0 (or +inf for no sliding that way)')
        else if (.not. finite_at_least(fr%static_factor, 1.0_dp)) then
            call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'static_factor = ' &
                           //real_str(fr%static_factor)//': must be a finite number >= 1')
        end if
    end subroutine friction_validate

    !> Stick-slip response to an idealized pulse of seispulse_pulses (SI or any
    !> consistent units; amp = 1, duration = 1 gives the dimensionless problem).
    !>
    !> Pieces (a_g continuous and monotone on each): exponential 0, t_d/2, t_d (3t_d/2,
    !> 2t_d); half-sine 0, T/2, T; sine cycle 0, T/4, 3T/4, T; cosine cycle 0, T/2, T;
    !> rectangular 0, T; triangular 0, rT, T. The spike (beta = +inf) exceeds any
    !> threshold at one instant only, so the block never slides. Ricker: from t = 0,
    !> breaks at the extrema x = pi f_p (t - t0) = -sqrt(1.5), 0, +sqrt(1.5), last
    !> piece cut at x = 10 (|a| < 1e-40 a_p), a_g = 0 after the cut. M&P: the extrema
    !> of a_g are not closed form: the window is cut into pieces of 1/(64 f_p), each
    !> split at the sign changes of the closed-form jerk (see seispulse_pieces).
    subroutine stickslip_pulse(p, fr, res, stat, errmsg, t_grid, u_grid, w_grid)
        type(pulse_t), intent(in) :: p                        !! the ground pulse
        type(friction_t), intent(in) :: fr                    !! friction of the block
        type(stickslip_result_t), intent(out) :: res          !! slides and summary
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        !> output times (units of the pulse), ascending; absent: no history (with u_grid,
        !> w_grid)
        real(dp), intent(in), optional :: t_grid(:)
        real(dp), intent(out), optional :: u_grid(:)          !! u at t_grid
        real(dp), intent(out), optional :: w_grid(:)          !! u' at t_grid
        type(ground_fn) :: g
        type(piece_iter_t) :: it
        real(dp) :: no_record(0)

        call empty_result(res)
        call friction_validate(fr, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call pulse_validate(p, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call pulse_pieces_check(p, 'stick-slip', stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call check_output_grid('u_grid', 'w_grid', stat, errmsg, t_grid, u_grid, w_grid)
        if (stat /= SEISPULSE_SUCCESS) return

        g%src = SRC_PULSE
        g%p = p
        if (p%kind == PULSE_EXPONENTIAL) g%cexp = exp_consts(p%beta)   ! once per run
        call pulse_pieces_init(it, p)
        call integrate(g, it, fr, no_record, res, stat, errmsg, t_grid, u_grid, w_grid)
    end subroutine stickslip_pulse

    !> Stick-slip response to an accelerogram in g (like `newmark_rigid` and
    !> `sdof_response`): accel(i) at t = (i - 1) dt, linear in between (each step is a
    !> piece), at rest before t = 0 and a_g = 0 after the last sample (a sliding block
    !> then decelerates to rest). The yield accelerations of `fr` are in g too; the run
    !> is made on accel(i) g and ay g (m/s^2), so u is in m and u' in m/s. g = 1 keeps
    !> any consistent units (accel and ay in the same units, u in those times s^2).
    subroutine stickslip_record(accel, dt, fr, g, res, stat, errmsg, t_grid, u_grid, w_grid)
        real(dp), intent(in) :: accel(:)                      !! ground acceleration (g), finite
        real(dp), intent(in) :: dt                            !! time step (s), > 0
        type(friction_t), intent(in) :: fr                    !! friction of the block (g)
        real(dp), intent(in) :: g                             !! unit g of accel, ay (m/s^2), > 0
        type(stickslip_result_t), intent(out) :: res          !! slides (u in m, u' in m/s)
                                                              !! and summary
        integer, intent(out) :: stat                          !! SEISPULSE_SUCCESS or error code
        character(len=*), intent(inout), optional :: errmsg  !! message when stat /= 0
        !> output times (s), ascending; absent: no history (with u_grid, w_grid)
        real(dp), intent(in), optional :: t_grid(:)
        real(dp), intent(out), optional :: u_grid(:)          !! u at t_grid (m)
        real(dp), intent(out), optional :: w_grid(:)          !! u' at t_grid (m/s)
        type(ground_fn) :: gf
        type(piece_iter_t) :: it
        type(friction_t) :: fr_si
        real(dp), allocatable :: accel_si(:)
        real(dp) :: big

        call empty_result(res)
        call friction_validate(fr, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        call record_step_check(accel, dt, g, stat, errmsg)   ! dt, g; not empty, finite
        if (stat /= SEISPULSE_SUCCESS) return
        call check_output_grid('u_grid', 'w_grid', stat, errmsg, t_grid, u_grid, w_grid)
        if (stat /= SEISPULSE_SUCCESS) return

        ! to m/s^2; ay g = +inf where the product would overflow (no sliding that way)
        call record_in_si(accel, g, accel_si, stat, errmsg)
        if (stat /= SEISPULSE_SUCCESS) return
        big = g_product_max(g)
        fr_si = fr
        fr_si%ay_fwd = ieee_value(g, ieee_positive_inf)
        fr_si%ay_rev = fr_si%ay_fwd
        if (fr%ay_fwd <= big) fr_si%ay_fwd = fr%ay_fwd * g
        if (fr%ay_rev <= big) fr_si%ay_rev = fr%ay_rev * g

        gf%src = SRC_RECORD
        call record_pieces_init(it, size(accel_si), dt)
        call integrate(gf, it, fr_si, accel_si, res, stat, errmsg, t_grid, u_grid, w_grid)
    end subroutine stickslip_record

    ! ------------------------------------------------------------------------------
    ! The integrator
    ! ------------------------------------------------------------------------------

    !> Run the event loop over the pieces of `it`; the ground is `g` (and `accel`).
    subroutine integrate(g, it, fr, accel, res, stat, errmsg, t_grid, u_grid, w_grid)
        type(ground_fn), intent(inout) :: g
        type(piece_iter_t), intent(inout) :: it
        type(friction_t), intent(in) :: fr
        real(dp), intent(in) :: accel(:)
        type(stickslip_result_t), intent(inout) :: res
        integer, intent(out) :: stat
        character(len=*), intent(inout), optional :: errmsg
        real(dp), intent(in), optional :: t_grid(:)
        real(dp), intent(out), optional :: u_grid(:)
        real(dp), intent(out), optional :: w_grid(:)

        type(slide_t), allocatable :: buf(:)
        type(slide_t) :: cur
        real(dp) :: t, u, w, ta, tb, aa, ab, a_c, thr_f, thr_r, lev, t_o, r, u_r, w_r
        real(dp) :: t_s, u_s, gc, gb, h, ay
        type(piece_t) :: piece
        integer :: mode, dir, blocked, last_dir, nslides, ig, ng, nev
        logical :: found, first_done, first_slide, just_stopped, now, split_done
        character(len=120) :: rmsg

        stat = SEISPULSE_SUCCESS
        allocate(buf(8))
        nslides = 0
        ng = 0
        if (present(t_grid)) ng = size(t_grid)
        ig = 1
        ! thresholds of the first onset (doc/sliding.md section 8); kinetic values after it
        thr_f = scaled_threshold(fr%ay_fwd, fr%static_factor)
        thr_r = scaled_threshold(fr%ay_rev, fr%static_factor)
        first_done = .false.
        first_slide = .false.
        just_stopped = .false.
        t = 0.0_dp
        u = 0.0_dp
        w = 0.0_dp
        mode = 0
        last_dir = 0
        a_c = 0.0_dp
        lev = 0.0_dp

        pieces: do
            call next_piece(it, accel, 'stickslip', piece, found, stat, errmsg)
            if (stat /= SEISPULSE_SUCCESS) return
            if (.not. found) exit pieces
            ta = piece%ta
            tb = piece%tb
            aa = piece%aa
            ab = piece%ab
            ! a record step is a line: load it into g (a pulse has its closed form)
            if (g%src == SRC_RECORD) then
                g%t0 = ta
                g%a0 = aa
                g%slope = piece%slope
            end if
            ! pieces are contiguous while sliding; at rest the block may wait for the first
            t = ta
            blocked = 0
            split_done = .false.
            a_c = aa
            if (mode /= 0) call set_reference(g, t, u, w, real(mode, dp) * ay_of(fr, mode))
            events: do nev = 1, max_events + 1
                if (nev > max_events) then
                    call set_error(stat, errmsg, SEISPULSE_INTERNAL, 'stickslip: too many ' &
                                   //'events on one piece near t = '//real_str(t)//' (a bug)')
                    return
                end if
                if (mode == 0) then
                    ! ---- at rest: onset on this piece? a_g is monotone, so the
                    ! largest excursion is at an end of [t, tb]
                    if (t >= tb) exit events
                    call onset_on_piece(a_c, ab, thr_f, thr_r, blocked, dir, lev, now)
                    if (dir == 0) then
                        call fill_rest(tb)
                        if (tb > t) just_stopped = .false.
                        t = tb
                        exit events
                    end if
                    t_o = t
                    if (.not. now) then
                        ! a_g - lev < 0 at t, > 0 at tb (or the mirror): one root
                        g%what = EVAL_ACCEL
                        g%level = lev
                        call find_root(g, t, tb, t_o, stat, rmsg, fa_known=a_c - lev, &
                                       fb_known=ab - lev)
                        if (stat /= SEISPULSE_SUCCESS) then
                            call root_failure('onset', t)
                            return
                        end if
                        t_o = min(max(t_o, t), tb)
                        if (t_o > t) then
                            just_stopped = .false.
                            a_c = accel_on_piece(t_o)
                        end if
                    end if
                    call fill_rest(t_o)
                    cur%direction = dir
                    cur%t_start = t_o
                    cur%u_start = u
                    cur%w_peak = 0.0_dp
                    cur%t_peak = t_o
                    cur%from_slip = just_stopped .and. dir == -last_dir
                    first_slide = .not. first_done
                    if (.not. first_done) then
                        first_done = .true.
                        if (.not. fr%static_all) then
                            thr_f = fr%ay_fwd
                            thr_r = fr%ay_rev
                        end if
                    end if
                    mode = dir
                    t = t_o
                    w = 0.0_dp
                    ! after an onset inside the piece a_g runs on past thr >= ay: u'' keeps
                    ! the sign of the slide to the piece end (no split; splitting at the
                    ! onset itself would see a zero-length slide)
                    split_done = .not. now
                    call set_reference(g, t, u, w, real(dir, dp) * ay_of(fr, dir))
                else
                    ! ---- sliding: split where u'' = a_g - s ay changes sign, so that u'
                    ! is monotone on [t, r]
                    r = tb
                    if (.not. split_done) then
                        gc = a_c - g%c
                        gb = ab - g%c
                        if ((gc < 0.0_dp .and. gb > 0.0_dp) .or. &
                            (gc > 0.0_dp .and. gb < 0.0_dp)) then
                            g%what = EVAL_ACCEL
                            g%level = g%c
                            call find_root(g, t, tb, r, stat, rmsg, fa_known=gc, fb_known=gb)
                            if (stat /= SEISPULSE_SUCCESS) then
                                call root_failure('peak velocity', t)
                                return
                            end if
                            r = min(max(r, t), tb)
                            split_done = .true.
                        end if
                    end if
                    call relative_state(g, r, u_r, w_r)
                    if (moving(mode, w_r)) then
                        ! no stop on [t, r]: r is a candidate for the peak velocity
                        call fill_slide(r)
                        if (abs(w_r) > cur%w_peak) then
                            cur%w_peak = abs(w_r)
                            cur%t_peak = r
                        end if
                        t = r
                        u = u_r
                        w = w_r
                        if (r >= tb) exit events
                        a_c = accel_on_piece(r)
                        cycle events
                    end if
                    ! u' reaches 0 in (t, r]: s w(t) > 0 >= s w(r), one root
                    if (moving(mode, w)) then
                        g%what = EVAL_VELOCITY
                        call find_root(g, t, r, t_s, stat, rmsg, fa_known=w, fb_known=w_r)
                        if (stat /= SEISPULSE_SUCCESS) then
                            call root_failure('stop', t)
                            return
                        end if
                        t_s = min(max(t_s, t), r)
                        call relative_state(g, t_s, u_s, w_r)
                    else
                        ! w = 0 at the onset and no push that way: no motion at all
                        t_s = t
                        u_s = u
                    end if
                    call fill_slide(t_s)
                    call close_slide(t_s, u_s)
                    a_c = accel_on_piece(t_s)
                end if
            end do events
        end do pieces

        ! after the excitation a_g = 0: uniform deceleration to rest
        if (mode /= 0) then
            ay = ay_of(fr, mode)
            if (ay < abs(w) / huge(w)) then
                call set_error(stat, errmsg, SEISPULSE_INVALID_INPUT, 'ay_fwd, ay_rev: too ' &
                               //'small for the final sliding velocity (the stop time overflows)')
                return
            end if
            h = abs(w) / ay
            do while (ig <= ng)
                if (t_grid(ig) > t + h) exit
                call decelerate(t_grid(ig) - t, u_grid(ig), w_grid(ig))
                ig = ig + 1
            end do
            call close_slide(t + h, u + 0.5_dp * w * h)
        end if
        do while (ig <= ng)
            u_grid(ig) = u
            w_grid(ig) = 0.0_dp
            ig = ig + 1
        end do

        res%u_final = u
        if (nslides == size(buf)) then
            call move_alloc(buf, res%slides)
        else
            if (allocated(res%slides)) deallocate(res%slides)
            allocate(res%slides(nslides))
            res%slides(:) = buf(1:nslides)
        end if

    contains

        !> a_g at t on the current piece, with the one-sided limits at its ends.
        function accel_on_piece(tt) result(a)
            real(dp), intent(in) :: tt
            real(dp) :: a
            if (tt >= tb) then
                a = ab
            else if (tt <= ta) then
                a = aa
            else
                a = ground_accel(g, tt)
            end if
        end function accel_on_piece

        !> Grid points up to tt while at rest.
        subroutine fill_rest(tt)
            real(dp), intent(in) :: tt
            do while (ig <= ng)
                if (t_grid(ig) > tt) exit
                u_grid(ig) = u
                w_grid(ig) = 0.0_dp
                ig = ig + 1
            end do
        end subroutine fill_rest

        !> Grid points up to tt on the current slide (reference state of g).
        subroutine fill_slide(tt)
            real(dp), intent(in) :: tt
            do while (ig <= ng)
                if (t_grid(ig) > tt) exit
                call relative_state(g, t_grid(ig), u_grid(ig), w_grid(ig))
                ig = ig + 1
            end do
        end subroutine fill_slide

        !> Free deceleration after the excitation, tau after t.
        subroutine decelerate(tau, ut, wt)
            real(dp), intent(in) :: tau
            real(dp), intent(out) :: ut, wt
            real(dp) :: cc
            cc = real(mode, dp) * ay
            ut = u + tau * (w - 0.5_dp * cc * tau)
            wt = w - cc * tau
        end subroutine decelerate

        !> End the current slide at tt with displacement uu; drop it if nothing moved.
        subroutine close_slide(tt, uu)
            real(dp), intent(in) :: tt, uu
            type(slide_t), allocatable :: tmp(:)
            if (tt > cur%t_start .and. cur%w_peak > 0.0_dp) then
                cur%t_stop = tt
                cur%u_stop = uu
                if (nslides == size(buf)) then
                    allocate(tmp(2 * nslides))
                    tmp(1:nslides) = buf(1:nslides)
                    call move_alloc(tmp, buf)
                end if
                nslides = nslides + 1
                buf(nslides) = cur
                u = uu
                res%u_max = max(res%u_max, uu)
                res%u_min = min(res%u_min, uu)
                res%t_end = tt
                last_dir = mode
                just_stopped = .true.
            else
                ! threshold touched, not exceeded: no slide, and none that way on this
                ! monotone piece (else the same onset would be found again)
                u = cur%u_start
                blocked = mode
                if (first_slide) then
                    ! not a real first onset: the static thresholds still hold
                    first_done = .false.
                    thr_f = scaled_threshold(fr%ay_fwd, fr%static_factor)
                    thr_r = scaled_threshold(fr%ay_rev, fr%static_factor)
                end if
            end if
            mode = 0
            w = 0.0_dp
            t = tt
        end subroutine close_slide

        subroutine root_failure(what, tt)
            character(len=*), intent(in) :: what
            real(dp), intent(in) :: tt
            call set_error(stat, errmsg, SEISPULSE_INTERNAL, 'stickslip: '//what// &
                           ' location failed after t = '//real_str(tt)//': '//trim(rmsg)// &
                           ' (a bug)')
        end subroutine root_failure

    end subroutine integrate

    ! ------------------------------------------------------------------------------
    ! Ground and relative motion on a piece
    ! ------------------------------------------------------------------------------

    function ground_eval(self, x) result(y)
        class(ground_fn), intent(inout) :: self
        real(dp), intent(in) :: x
        real(dp) :: y
        real(dp) :: ux
        if (self%what == EVAL_ACCEL) then
            y = ground_accel(self, x) - self%level
        else
            call relative_state(self, x, ux, y)
        end if
    end function ground_eval

    !> Ground acceleration at t inside the current piece.
    pure function ground_accel(g, t) result(a)
        type(ground_fn), intent(in) :: g
        real(dp), intent(in) :: t
        real(dp) :: a
        real(dp) :: v, d
        if (g%src == SRC_PULSE) then
            call pulse_at(g%p, t, a, v, d, g%cexp)
        else
            a = g%a0 + g%slope * (t - g%t0)
        end if
    end function ground_accel

    !> Start propagating the relative motion from (t, u, w) with u'' = a_g - c.
    pure subroutine set_reference(g, t, u, w, c)
        type(ground_fn), intent(inout) :: g
        real(dp), intent(in) :: t, u, w, c
        real(dp) :: a
        g%t_ref = t
        g%u_ref = u
        g%w_ref = w
        g%c = c
        if (g%src == SRC_PULSE) then
            call pulse_at(g%p, t, a, g%v_ref, g%d_ref, g%cexp)
        else
            g%a_ref = g%a0 + g%slope * (t - g%t0)
        end if
    end subroutine set_reference

    !> Relative displacement and velocity at t from the reference state (Eqs. 1.4-1.5
    !> with ground increments from t_ref; a record step in its local polynomial).
    pure subroutine relative_state(g, t, u, w)
        type(ground_fn), intent(in) :: g
        real(dp), intent(in) :: t
        real(dp), intent(out) :: u, w
        real(dp) :: h, a, v, d
        h = t - g%t_ref
        if (g%src == SRC_PULSE) then
            call pulse_at(g%p, t, a, v, d, g%cexp)
            w = g%w_ref + (v - g%v_ref) - g%c * h
            u = g%u_ref + g%w_ref * h + ((d - g%d_ref) - g%v_ref * h) - 0.5_dp * g%c * h * h
        else
            w = g%w_ref + h * (g%a_ref - g%c + 0.5_dp * g%slope * h)
            u = g%u_ref + h * (g%w_ref + h * (0.5_dp * (g%a_ref - g%c) &
                                              + g%slope * h / 6.0_dp))
        end if
    end subroutine relative_state

    ! ------------------------------------------------------------------------------
    ! Small helpers
    ! ------------------------------------------------------------------------------

    !> True while the block still moves in direction `mode` with velocity w.
    elemental logical function moving(mode, w)
        integer, intent(in) :: mode
        real(dp), intent(in) :: w
        moving = (mode > 0 .and. w > 0.0_dp) .or. (mode < 0 .and. w < 0.0_dp)
    end function moving

    pure function ay_of(fr, dir) result(ay)
        type(friction_t), intent(in) :: fr
        integer, intent(in) :: dir
        real(dp) :: ay
        if (dir > 0) then
            ay = fr%ay_fwd
        else
            ay = fr%ay_rev
        end if
    end function ay_of

    !> factor * ay without overflow (+inf when it would overflow or ay = +inf).
    function scaled_threshold(ay, factor) result(thr)
        real(dp), intent(in) :: ay, factor
        real(dp) :: thr
        if (ay > huge(ay) / factor) then
            thr = ieee_value(thr, ieee_positive_inf)
        else
            thr = factor * ay
        end if
    end function scaled_threshold

    !> A well-defined result for the error returns.
    subroutine empty_result(res)
        type(stickslip_result_t), intent(inout) :: res
        if (allocated(res%slides)) deallocate(res%slides)
        allocate(res%slides(0))
        res%u_final = 0.0_dp
        res%u_max = 0.0_dp
        res%u_min = 0.0_dp
        res%t_end = 0.0_dp
    end subroutine empty_result

end module seispulse_sliding_sim
