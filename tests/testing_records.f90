!> What the suites of records (rates, point, split) share: the laboratory rigs of their
!! records, the records the model makes of them with noise (a 3-axis gyro, a video track),
!! a track written as a tracker's file, the model's states along a run (for its pose), the
!! model's derivatives against differences of whole runs, and a record fitted for I1 and
!! t0 against their truth.  Apart from module testing, whose harness uses nothing of the
!! model: a change of the record fit rebuilds the suites that use these, not every suite.
module testing_records
    use kinds, only: dp, deg
    use status, only: status_t
    use testing, only: tester_t, msg_of, write_text
    use deck, only: deck_t, read_deck
    use rig, only: rig_t, start_t, accuracy_t, make_pendulum, start_state
    use geometry, only: pendulum_t
    use bifilar_model, only: NSTATE
    use kane_run, only: kane_run_t, kane_run_start
    use run_loop, only: drive
    use keep_sink, only: keep_t
    use record_fit, only: record_model, record_model_sens
    use inputs, only: set_input, input_value
    use records, only: record_t
    use identify, only: identify_result_t, identify_record
    use random, only: rng_t, rng_stream, rng_normal
    implicit none
    private

    public :: lab_rig, turned_rig, video_rig, make_gyro, make_track, write_track, pose_states
    public :: check_sens, check_release_fit

    !> A video track's camera: m per px, the origin of the point at zero angles (px), the
    !! tracker's noise (px)
    real(dp), parameter, public :: TRACK_SCALE = 5.0e-4_dp
    real(dp), parameter, public :: TRACK_ORIGIN(2) = [640.0_dp, 360.0_dp]
    real(dp), parameter, public :: TRACK_NOISE = 0.3_dp

contains

    !> The laboratory rig of input/identify_record.nml (unequal cables, the mass centre off
    !! the midpoint of CD, no damping) at its true moments, released from 30 degrees with a
    !! tilt of 2 degrees and a sway of 1 cm (l sway); rtol 1e-10, atol 1e-12.
    subroutine lab_rig(rg, st, acc)
        type(rig_t), intent(out) :: rg
        type(start_t), intent(out) :: st
        type(accuracy_t), intent(out) :: acc
        rg%b = 0.40_dp
        rg%b_prime = 0.40_dp
        rg%l = 1.20_dp
        rg%l_prime = 1.18_dp
        rg%g = 9.80665_dp
        rg%mass = 3.10_dp
        rg%inertia = [0.0512_dp, 0.0630_dp, 0.0304_dp]
        rg%r = 0.25_dp
        rg%lambda = 0.64_dp
        rg%sway_depth = 0.30_dp
        rg%c_v = 0.0_dp
        rg%c_q = 0.0_dp
        st%mode = 'raised'
        st%amplitude = 30.0_dp
        st%tilt = 2.0_dp*deg
        st%sway = 0.01_dp/rg%l
        acc%rtol = 1.0e-10_dp
        acc%atol = 1.0e-12_dp
    end subroutine lab_rig

    !> lab_rig's, its principal axes turned by 0.3 rad about ntilde_2 (the rows of btilde:
    !! b_i in ntilde).
    subroutine turned_rig(rg, st, acc)
        type(rig_t), intent(out) :: rg
        type(start_t), intent(out) :: st
        type(accuracy_t), intent(out) :: acc
        real(dp) :: c, s
        call lab_rig(rg, st, acc)
        c = cos(0.3_dp)
        s = sin(0.3_dp)
        rg%btilde = reshape([c, 0.0_dp, -s, 0.0_dp, 1.0_dp, 0.0_dp, s, 0.0_dp, c], [3, 3])
    end subroutine turned_rig

    !> The rig of the video tracks: lab_rig's made symmetric (equal cables, the mass centre
    !! on the axis, 20 cm below CD), released from 20 degrees, no tilt, no sway.
    subroutine video_rig(rg, st, acc)
        type(rig_t), intent(out) :: rg
        type(start_t), intent(out) :: st
        type(accuracy_t), intent(out) :: acc
        call lab_rig(rg, st, acc)
        rg%l_prime = 1.20_dp
        rg%r = 0.20_dp
        rg%lambda = 0.0_dp
        st%amplitude = 20.0_dp
        st%tilt = 0.0_dp
        st%sway = 0.0_dp
    end subroutine video_rig

    !> A 3-axis gyro's record of the rig at the times t, released at t0: the model's three
    !! rates read along axes, each over its scale, plus its bias and normal noise sigma
    !! (rad/s) from stream `stream` of seed (axis by axis); v the rate about the vertical,
    !! -vs(1:n).
    subroutine make_gyro(rg, st, acc, t, t0, axes, bias, scales, sigma, seed, stream, rec, stat)
        type(rig_t), intent(in) :: rg
        type(start_t), intent(in) :: st
        type(accuracy_t), intent(in) :: acc
        real(dp), intent(in) :: t(:), t0        !! s
        real(dp), intent(in) :: axes(3, 3)      !! the instrument's axes (record_axes)
        real(dp), intent(in) :: bias(3), scales(3), sigma
        integer, intent(in) :: seed, stream
        type(record_t), intent(out) :: rec
        type(status_t), intent(out) :: stat
        type(rng_t) :: g
        real(dp) :: vals(3*size(t))
        integer :: i, k, n
        n = size(t)
        allocate (rec%t(n), rec%v(n), rec%u(n), rec%vs(3*n))
        rec%t = t
        call record_model(rg, st, acc, rec%t, t0, .true., vals, stat, axes)
        if (stat%code /= 0) return
        g = rng_stream(seed, stream)
        do k = 1, 3
            do i = 1, n
                rec%vs((k - 1)*n + i) = vals((k - 1)*n + i)/scales(k) + bias(k) + &
                                        sigma*rng_normal(g)
            end do
        end do
        rec%v = -rec%vs(1:n)
        rec%u = 1.0_dp
        rec%rate = .true.
        rec%units = 'rad/s'
    end subroutine make_gyro

    !> A video track of the point q (m, the body's principal axes from the mass centre) at
    !! the times t, released at t0, seen from view (record_fit's VIEW_BELOW or VIEW_SIDE):
    !! the model's two coordinates in px (TRACK_SCALE), from TRACK_ORIGIN, plus normal noise
    !! TRACK_NOISE from stream `stream` of seed (coordinate by coordinate); v the first.
    subroutine make_track(rg, st, acc, t, t0, q, seed, stream, rec, stat, view)
        type(rig_t), intent(in) :: rg
        type(start_t), intent(in) :: st
        type(accuracy_t), intent(in) :: acc
        real(dp), intent(in) :: t(:), t0        !! s
        real(dp), intent(in) :: q(3)            !! m
        integer, intent(in) :: seed, stream
        type(record_t), intent(out) :: rec
        type(status_t), intent(out) :: stat
        integer, intent(in), optional :: view
        type(rng_t) :: g
        real(dp) :: vals(2*size(t))
        integer :: i, k, n
        n = size(t)
        allocate (rec%t(n), rec%v(n), rec%u(n), rec%vs(2*n))
        rec%t = t
        call record_model(rg, st, acc, rec%t, t0, .false., vals, stat, point=q, view=view)
        if (stat%code /= 0) return
        g = rng_stream(seed, stream)
        do k = 1, 2
            do i = 1, n
                rec%vs((k - 1)*n + i) = vals((k - 1)*n + i)/TRACK_SCALE + TRACK_ORIGIN(k) + &
                                        TRACK_NOISE*rng_normal(g)
            end do
        end do
        rec%v = rec%vs(1:n)
        rec%u = 1.0_dp
        rec%units = 'px'
    end subroutine make_track

    !> A track (rec) as a tracker's file at path: the header head, then the time (s, or the
    !! frame numbers from 0 when frames) and x, y (px, times unit: one px in the file's
    !! unit; x alone unless both).
    subroutine write_track(path, rec, head, frames, both, unit)
        character(len=*), intent(in) :: path, head
        type(record_t), intent(in) :: rec
        logical, intent(in) :: frames, both
        real(dp), intent(in) :: unit
        character(len=:), allocatable :: text
        character(len=80) :: line
        integer :: j, n
        n = size(rec%t)
        text = head//new_line('a')
        do j = 1, n
            if (frames) then
                write (line, '(i0,2(", ",f0.5))') j - 1, rec%vs(j)*unit, rec%vs(n + j)*unit
            else
                write (line, '(es23.15,2(", ",f0.6))') rec%t(j), rec%vs(j)*unit, &
                    rec%vs(n + j)*unit
            end if
            if (.not. both) line = line(1:index(line, ',', back=.true.) - 1)
            text = text//trim(line)//new_line('a')
        end do
        call write_text(path, text)
    end subroutine write_track

    !> The model's states at the times taus (tau = t sqrt(g/b'), increasing) of the run
    !! from the start: ys(:, i) at taus(i); p the rig's pendulum.
    subroutine pose_states(rg, st, acc, taus, p, ys, stat)
        type(rig_t), intent(in) :: rg
        type(start_t), intent(in) :: st
        type(accuracy_t), intent(in) :: acc
        real(dp), intent(in) :: taus(0:)
        type(pendulum_t), intent(out) :: p
        real(dp), allocatable, intent(out) :: ys(:, :)
        type(status_t), intent(out) :: stat
        type(kane_run_t) :: m
        type(keep_t) :: sink
        real(dp) :: y0(NSTATE), th0(5)
        integer :: nt
        nt = size(taus)
        call make_pendulum(rg, p, stat)
        if (stat%code == 0) call start_state(st, p, y0, th0, stat)
        if (stat%code == 0) call kane_run_start(m, p, y0, th0(3), acc%rtol, acc%atol, &
                                                acc%method, taus(nt - 1), 'rtol', stat)
        allocate (sink%ys(NSTATE, 0:nt - 1))
        if (stat%code == 0) call drive(m, taus, sink, stat)
        call move_alloc(sink%ys, ys)
    end subroutine pose_states

    !> The model's derivatives (record_model_sens: forward sensitivities) along the
    !! quantities names (sizes xs) at the times ts against central differences of whole
    !! runs, extrapolated (error h^4, h = 2e-3 of each size): for each, a check that the
    !! worst difference, times its size, over the largest value is within 1e-5, and one
    !! that the quantity moves the values (by more than 1e-6 of the largest).  what: the
    !! values' name in the labels ('rates' with axes, 'point' with point), big: what the
    !! largest value is ('rate', 'excursion').
    subroutine check_sens(t, what, big_word, rg, st, acc, ts, names, xs, axes, point)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: what, big_word
        type(rig_t), intent(in) :: rg
        type(start_t), intent(in) :: st
        type(accuracy_t), intent(in) :: acc
        real(dp), intent(in) :: ts(:)
        character(len=*), intent(in) :: names(:)
        real(dp), intent(in) :: xs(:)
        real(dp), intent(in), optional :: axes(3, 3), point(3)
        type(status_t) :: stat
        real(dp), allocatable :: vals(:), dv(:, :), vp(:), vm(:), fd(:)
        real(dp) :: h, big
        integer :: c, nv
        nv = 2*size(ts)
        if (present(axes)) nv = 3*size(ts)
        allocate (vals(nv), dv(nv, size(names)), vp(nv), vm(nv), fd(nv))
        call record_model_sens(rg, st, acc, ts, 0.0_dp, present(axes), names, xs, vals, dv, &
                               stat, axes, point)
        call t%check(what//': the sensitivities'' run'//msg_of(stat), stat%code == 0)
        if (stat%code /= 0) return
        big = maxval(abs(vals))
        do c = 1, size(names)
            h = 2.0e-3_dp*xs(c)
            call moved(names(c), h, vp)
            call moved(names(c), -h, vm)
            fd = -(vp - vm)/(2.0_dp*h)/3.0_dp
            call moved(names(c), 0.5_dp*h, vp)
            call moved(names(c), -0.5_dp*h, vm)
            fd = fd + 4.0_dp/3.0_dp*(vp - vm)/h
            call t%check_close(what//': d '//what//'/d '//trim(names(c))//' against '// &
                               'differences (worst, times its size, over the largest '// &
                               big_word//')', maxval(abs(dv(:, c) - fd))*xs(c)/big, 0.0_dp, &
                               0.0_dp, 1.0e-5_dp)
            call t%check(what//': '//trim(names(c))//' moves the '//what, &
                         maxval(abs(fd))*xs(c) > 1.0e-6_dp*big)
        end do
    contains
        !> The values with the quantity name moved by dx.
        subroutine moved(name, dx, v)
            character(len=*), intent(in) :: name
            real(dp), intent(in) :: dx
            real(dp), intent(out) :: v(:)
            type(rig_t) :: r2
            type(start_t) :: s2
            type(status_t) :: s
            r2 = rg
            s2 = st
            select case (trim(name))
            case ('I1')
                r2%inertia(1) = rg%inertia(1) + dx
            case ('tilt')
                s2%tilt = st%tilt + dx
            case ('sway')
                s2%sway = st%sway + dx
            case ('amplitude')
                s2%amplitude = st%amplitude + dx
            case default
                call set_input(r2, s2, name, input_value(rg, st, name) + dx)
            end select
            call record_model(r2, s2, acc, ts, 0.0_dp, present(axes), v, s, axes, point)
        end subroutine moved
    end subroutine check_sens

    !> The deck at deck_path read and its record rec fitted (identify_record) for I1 and
    !! t0: checks that the deck reads, the fit converges, I1 and t0 (estimated) each within
    !! max(k, 1.96) u of their truth, labelled 'rates: WHAT: ...', with the values printed.
    !! deck_ok: the deck was read (the caller stops when not).
    subroutine check_release_fit(t, what, deck_path, rec, i1_true, t0_true, deck_ok)
        type(tester_t), intent(inout) :: t
        character(len=*), intent(in) :: what, deck_path
        type(record_t), intent(in) :: rec
        real(dp), intent(in) :: i1_true, t0_true
        logical, intent(out) :: deck_ok
        type(deck_t) :: d
        type(identify_result_t) :: res
        type(status_t) :: stat
        integer :: j
        call read_deck(deck_path, d, stat)
        deck_ok = stat%code == 0
        call t%check('rates: '//trim(what)//': the deck'//msg_of(stat), deck_ok)
        if (.not. deck_ok) return
        call identify_record(d, rec, res, stat)
        call t%check('rates: '//trim(what)//': the fit'//msg_of(stat), stat%code == 0)
        if (stat%code /= 0) return
        print '(a,3es14.6)', '   '//what//' I1, truth, U: ', res%i1, i1_true, res%k*res%u_i1
        call t%check('rates: '//trim(what)//': I1 within U', &
                     abs(res%i1 - i1_true) <= max(res%k, 1.96_dp)*res%u_i1)
        j = findloc(res%names(1:res%np), 't0', 1)
        call t%check('rates: '//trim(what)//': t0 estimated', j > 0)
        if (j == 0) return
        print '(a,3es14.6)', '   '//what//' t0, truth, u: ', res%p(j), t0_true, res%u_p(j)
        call t%check('rates: '//trim(what)//': t0 within U', &
                     abs(res%p(j) - t0_true) <= max(res%k, 1.96_dp)*res%u_p(j))
    end subroutine check_release_fit

end module testing_records
