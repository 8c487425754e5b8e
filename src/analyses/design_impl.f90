!> The implementation of the rig design (submodule of design): the three sweeps (Floquet
!! points, band edges, precision), the bands, the recommendation and the file.
submodule (design) design_impl
    use kinds, only: dp
    use finite, only: finite_bits
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK, ERR_MODEL, ERR_NUMERIC
    use text, only: itoa, sci, fixed
    use deck, only: deck_t, deck_echo
    use geometry, only: pendulum_t
    use rig, only: rig_t, accuracy_t, make_pendulum, move_b_prime
    use deck_runs, only: rig_of, accuracy_of, undamped_ready
    use floquet, only: check_torsion_scene, STABILITY_MARGIN, floquet_point, CHART_INVALID, &
                       CHART_FAILED, point_values_valid
    use sweep_engine, only: sweep_task_t, sweep_run, sweep_options_t, sweep_report_t, &
        checkpoint_path
    use period_inversion, only: period_fit_t, torsion_period_s, invert_periods, &
                                period_budget, linear_inertia
    use output_io, only: out_files_t, write_kv, remove_file
    use unused_arg, only: unused
    use analysis_base, only: ranks_note, resume_note
    implicit none

    !> Sweep 1: Floquet point k = (amplitude j, l i, b m), amplitude fastest; value: the
    !! largest multiplier (or a sentinel).
    type, extends(sweep_task_t) :: floquet_work_t
        type(design_rig_t) :: dr
        real(dp), allocatable :: ls(:), bs(:), bps(:), amps(:)
    contains
        procedure :: compute => floquet_work_point
        procedure :: accepts => floquet_work_accepts
    end type floquet_work_t

    !> Sweep 2: edge e between l(il(e)) and l(il(e) + 1) at b(ib(e)), amplitude ia(e), with
    !! stability left_stable(e) at the left end; values: the edge and the Floquet points
    !! the bisection took.
    type, extends(sweep_task_t) :: edge_work_t
        type(design_rig_t) :: dr
        real(dp), allocatable :: ls(:), bs(:), bps(:), amps(:)
        integer, allocatable :: il(:), ib(:), ia(:)
        logical, allocatable :: left_stable(:)
    contains
        procedure :: compute => edge_work_point
        procedure :: accepts => edge_work_accepts
    end type edge_work_t

    !> Sweep 3: candidate c = (l i, b m), l fastest; values: period (s), u(I1)/I1, linear
    !! error (-1 each when the period cannot be computed).
    type, extends(sweep_task_t) :: precision_work_t
        type(design_rig_t) :: dr
        real(dp), allocatable :: ls(:), bs(:), bps(:)
        real(dp) :: amp = 0.0_dp                !! amplitude_measure (deg)
        type(input_u_t) :: u
    contains
        procedure :: compute => precision_work_point
        procedure :: accepts => precision_work_accepts
    end type precision_work_t

contains

    !> What the candidates of deck d are made from.
    module procedure design_rig_of
        dr%rg = rig_of(d)
        dr%acc = accuracy_of(d)
        dr%fq_rtol = d%floquet%rtol
        dr%fq_segments = d%floquet%segments
    end procedure design_rig_of

    !> The rig with the candidate's cables l = l', support spacing b and body spacing b'.
    module procedure candidate_rig
        rr = rg
        rr%l = l
        rr%l_prime = l
        rr%b = b
        if (bp /= rg%b_prime) call move_b_prime(rr, bp)
    end procedure candidate_rig

    !> The candidate grid of &design: l from l_min to l_max (nl values), the spacing pairs
    !! (b fastest), amplitudes j amplitude_max / n_amplitudes.
    module procedure design_grid
        integer :: i, j
        real(dp), allocatable :: b1(:), bp1(:)
        allocate (ls(d%design%nl), amps(d%design%n_amplitudes))
        do i = 1, d%design%nl
            ls(i) = d%design%l_min + (d%design%l_max - d%design%l_min)*(i - 1)/(d%design%nl - 1)
        end do
        ls(d%design%nl) = d%design%l_max
        b1 = spacings(d%design%b_min, d%design%b_max, d%design%nb, d%suspension%b)
        bp1 = spacings(d%design%b_prime_min, d%design%b_prime_max, d%design%nb_prime, &
                       d%suspension%b_prime)
        allocate (bs(size(b1)*size(bp1)), bps(size(b1)*size(bp1)))
        do j = 1, size(bp1)
            do i = 1, size(b1)
                bs(i + size(b1)*(j - 1)) = b1(i)
                bps(i + size(b1)*(j - 1)) = bp1(j)
            end do
        end do
        do i = 1, d%design%n_amplitudes
            amps(i) = d%design%amplitude_max*i/d%design%n_amplitudes
        end do
        amps(d%design%n_amplitudes) = d%design%amplitude_max
    contains
        !> n spacings from lo to hi; with n = 1, lo (the deck's value when lo = 0).
        pure function spacings(lo, hi, n, deck_value) result(v)
            real(dp), intent(in) :: lo, hi, deck_value
            integer, intent(in) :: n
            real(dp), allocatable :: v(:)
            integer :: k
            allocate (v(n))
            if (n == 1) then
                v(1) = lo
                if (lo == 0.0_dp) v(1) = deck_value
                return
            end if
            do k = 1, n
                v(k) = lo + (hi - lo)*(k - 1)/(n - 1)
            end do
            v(n) = hi
        end function spacings
    end procedure design_grid

    !> The preconditions of analyses = 'design', before any computing: pure torsion is an
    !! exact motion of the deck's body on equal cables, with b1 the vertical principal axis
    !! (its I1 is the one measured), and u_period lies below the shortest period of the
    !! candidates (ERR_DECK otherwise).
    module procedure design_ready
        type(pendulum_t) :: p
        real(dp), allocatable :: ls(:), bs(:), bps(:), amps(:)
        real(dp) :: t, tmin, lmin, bmin
        integer :: ivert, i, m
        type(status_t) :: st
        type(rig_t) :: rg
        call design_grid(d, ls, bs, bps, amps)
        rg = rig_of(d)
        ! (whether the cables reach is each candidate's own matter: -1 in the table)
        call make_pendulum(candidate_rig(rg, ls(size(ls)), bs(size(bs)), bps(size(bps))), p, &
                           st)
        call check_torsion_scene(p, ivert, stat)
        if (stat%code == STATUS_OK .and. ivert /= 1) call set_error(stat, ERR_DECK, &
            '&body btilde: b1 is not vertical at rest (row 1 must be (+-1, 0, 0)): the '// &
            'period of torsion does not measure I1')
        if (stat%code /= STATUS_OK) then
            stat%msg = 'analyses = ''design'' needs a body for which pure torsion on equal '// &
                'cables is an exact motion: '//stat%msg
            return
        end if
        tmin = huge(1.0_dp)
        lmin = 0.0_dp
        bmin = 0.0_dp
        do m = 1, size(bs)
            do i = 1, size(ls)
                call torsion_period_s(candidate_rig(rg, ls(i), bs(m), bps(m)), rg%inertia(1), &
                                      d%design%amplitude_measure, t, st)
                if (st%code /= STATUS_OK) cycle
                if (t < tmin) then
                    tmin = t
                    lmin = ls(i)
                    bmin = bs(m)
                end if
            end do
        end do
        if (tmin < huge(1.0_dp) .and. d%design%u_period >= tmin) call set_error(stat, ERR_DECK, &
            '&design u_period = '//num(d%design%u_period)//' s: not below the shortest '// &
            'period of the candidates ('//num(tmin)//' s at l = '//num(lmin)//', b = '// &
            num(bmin)//'); allowed: 0 <= u_period < '//num(tmin)//' s')
    end procedure design_ready

    !> The largest Floquet multiplier of pure torsion of candidate (l, b, b') at amp_deg,
    !! with the deck's &floquet rtol and segments (CHART_INVALID, CHART_FAILED as in a chart).
    module procedure candidate_modulus
        type(pendulum_t) :: p
        type(status_t) :: st
        real(dp) :: period
        modulus = CHART_INVALID
        call make_pendulum(candidate_rig(dr%rg, l, b, bp), p, st)
        if (st%code /= STATUS_OK) return
        call floquet_point(p, amp_deg, dr%fq_rtol, dr%fq_segments, modulus, period, &
                           dr%acc%method, dr%acc%sensitivities)
    end procedure candidate_modulus

    !> Stable by the design's criterion: a real modulus (no sentinel) <= 1 + tolerance.
    pure logical function is_stable(modulus)
        real(dp), intent(in) :: modulus
        is_stable = modulus >= 0.0_dp .and. modulus <= 1.0_dp + DESIGN_TOLERANCE
    end function is_stable

    !> Sweep 1's point k.
    subroutine floquet_work_point(self, i, values, stat)
        class(floquet_work_t), intent(in) :: self
        integer, intent(in) :: i
        real(dp), intent(out) :: values(:)
        type(status_t), intent(out) :: stat     !! always OK (sentinels in values)
        integer :: na, nl, j, ic, m
        stat%code = STATUS_OK
        na = size(self%amps)
        nl = size(self%ls)
        j = mod(i - 1, na) + 1
        ic = mod((i - 1)/na, nl) + 1
        m = (i - 1)/(na*nl) + 1
        call candidate_modulus(self%dr, self%ls(ic), self%bs(m), self%bps(m), self%amps(j), &
                               values(1))
    end subroutine floquet_work_point

    !> Sweep 1's point i as read back from a checkpoint: a modulus as floquet_point gives it.
    logical function floquet_work_accepts(self, i, values) result(ok)
        class(floquet_work_t), intent(in) :: self
        integer, intent(in) :: i
        real(dp), intent(in) :: values(:)
        ok = size(values) == 1 .and. i >= 1 .and. &
            i <= size(self%amps)*size(self%ls)*size(self%bs)
        if (ok) ok = point_values_valid(values(1))
    end function floquet_work_accepts

    !> Sweep 2's edge i as read back from a checkpoint: inside its bracket of l, after a
    !! whole number of bisection steps (at most 200: each halves the bracket).
    logical function edge_work_accepts(self, i, values) result(ok)
        class(edge_work_t), intent(in) :: self
        integer, intent(in) :: i
        real(dp), intent(in) :: values(:)
        ok = size(values) == 2 .and. i >= 1 .and. i <= size(self%il)
        if (.not. ok) return
        ok = all(finite_bits(values))
        if (.not. ok) return
        ok = values(1) >= self%ls(self%il(i)) .and. values(1) <= self%ls(self%il(i) + 1) .and. &
            values(2) >= 0.0_dp .and. values(2) <= 200.0_dp .and. values(2) == aint(values(2))
    end function edge_work_accepts

    !> Sweep 3's candidate i as read back from a checkpoint: a period > 0, u(I1)/I1 >= 0 and
    !! a linear error > -1, all finite, or CHART_INVALID in all three.
    logical function precision_work_accepts(self, i, values) result(ok)
        class(precision_work_t), intent(in) :: self
        integer, intent(in) :: i
        real(dp), intent(in) :: values(:)
        ok = size(values) == 3 .and. i >= 1 .and. i <= size(self%ls)*size(self%bs)
        if (ok) ok = all(finite_bits(values))
        if (.not. ok) return
        if (all(values == CHART_INVALID)) return
        ok = values(1) > 0.0_dp .and. values(2) >= 0.0_dp .and. values(3) > -1.0_dp
    end function precision_work_accepts

    !> Sweep 2's edge e: bisection in l until the bracket is at most EDGE_RTOL l; the edge is
    !! the bracket's midpoint.
    subroutine edge_work_point(self, i, values, stat)
        class(edge_work_t), intent(in) :: self
        integer, intent(in) :: i
        real(dp), intent(out) :: values(:)
        type(status_t), intent(out) :: stat     !! always OK
        real(dp) :: lo, hi, mid, modulus
        integer :: n
        stat%code = STATUS_OK
        lo = self%ls(self%il(i))
        hi = self%ls(self%il(i) + 1)
        n = 0
        do while (hi - lo > EDGE_RTOL*hi)
            mid = 0.5_dp*(lo + hi)
            if (.not. (mid > lo .and. mid < hi)) exit
            call candidate_modulus(self%dr, mid, self%bs(self%ib(i)), self%bps(self%ib(i)), &
                                   self%amps(self%ia(i)), modulus)
            n = n + 1
            if (is_stable(modulus) .eqv. self%left_stable(i)) then
                lo = mid
            else
                hi = mid
            end if
        end do
        values(1) = 0.5_dp*(lo + hi)
        values(2) = n
    end subroutine edge_work_point

    !> Sweep 3's candidate c.
    subroutine precision_work_point(self, i, values, stat)
        class(precision_work_t), intent(in) :: self
        integer, intent(in) :: i
        real(dp), intent(out) :: values(:)
        type(status_t), intent(out) :: stat     !! always OK (sentinels in values)
        type(status_t) :: st
        integer :: ic, m
        stat%code = STATUS_OK
        ic = mod(i - 1, size(self%ls)) + 1
        m = (i - 1)/size(self%ls) + 1
        call candidate_precision(self%dr, self%ls(ic), self%bs(m), self%bps(m), self%amp, &
                                 self%u, values(1), values(2), values(3), st)
        if (st%code /= STATUS_OK) values(1:3) = CHART_INVALID
    end subroutine precision_work_point

    !> The precision of candidate (l, b, b') measured by one period at amp_deg: its exact
    !! period (s), I1 inverted back from it (invert_periods) and the first-order budget of
    !! that inversion (period_budget): u(I1)/I1; and the linear formula's relative error
    !! there.
    module procedure candidate_precision
        type(rig_t) :: dd
        type(period_fit_t) :: fit
        period_s = CHART_INVALID
        u_rel = CHART_INVALID
        linear_error = CHART_INVALID
        dd = candidate_rig(dr%rg, l, b, bp)
        call torsion_period_s(dd, dd%inertia(1), amp_deg, period_s, stat)
        if (stat%code /= STATUS_OK) return
        call invert_periods(dd, dr%acc, [period_s], [amp_deg], u, fit, stat)
        if (stat%code == STATUS_OK) call period_budget(dd, dr%acc, [period_s], [amp_deg], u, &
                                                       fit, stat)
        if (stat%code /= STATUS_OK) return
        if (.not. (fit%i1 > 0.0_dp .and. fit%u_i1 >= 0.0_dp .and. fit%u_i1 < huge(1.0_dp))) then
            call set_error(stat, ERR_NUMERIC, 'design: the uncertainty budget is not finite')
            return
        end if
        u_rel = fit%u_i1/fit%i1
        linear_error = linear_inertia(dd, period_s)/dd%inertia(1) - 1.0_dp
    end procedure candidate_precision

    !> The whole design of deck d (without writing): the three sweeps, the bands, the
    !! margins and the recommendation (res%found).  `label` names the progress lines.  With
    !! `outdir` the sweeps are checkpointed there (options: --resume, the interval); stat
    !! and report say how the sweeps went (a failure: a rank that cannot take part, a
    !! checkpoint that cannot be written).
    module procedure design_sweep
        type(floquet_work_t) :: fw
        type(edge_work_t) :: ew
        type(precision_work_t) :: pw
        type(status_t) :: st
        type(sweep_report_t) :: rep, all
        real(dp), allocatable :: vals(:, :)
        integer :: na, nl, nb, i, j, m, e, ne
        logical, allocatable :: sta(:, :, :)

        all%note = ''
        all%warning = ''
        call design_grid(d, res%ls, res%bs, res%bps, res%amps)
        na = size(res%amps)
        nl = size(res%ls)
        nb = size(res%bs)
        res%n_grid_points = na*nl*nb
        res%wall_seconds = 0.0_dp

        run: block
            ! 1. the grid's Floquet points
            call fill_task(d, [real(dp) ::], fw)
            call sweep_run(fw, trim(DESIGN_STAGES(1)), d%path, ckpt(1), plabel('Floquet points'), &
                           na*nl*nb, 1, vals, st, options, rep, deck_text=d%text)
            call add(rep)
            if (st%code /= STATUS_OK) exit run
            res%modulus = reshape(vals(1, :), [na, nl, nb])
            res%n_failed = count(res%modulus == CHART_FAILED)
            allocate (sta(na, nl, nb))
            do m = 1, nb
                do i = 1, nl
                    do j = 1, na
                        sta(j, i, m) = is_stable(res%modulus(j, i, m))
                    end do
                end do
            end do

            ! 2. the edges, one bisection each, in index order (b, amplitude, l)
            ne = 0
            do m = 1, nb
                do j = 1, na
                    ne = ne + count(sta(j, 1:nl - 1, m) .neqv. sta(j, 2:nl, m))
                end do
            end do
            res%n_edges = ne
            allocate (ew%il(ne), ew%ib(ne), ew%ia(ne), ew%left_stable(ne))
            e = 0
            do m = 1, nb
                do j = 1, na
                    do i = 1, nl - 1
                        if (sta(j, i, m) .eqv. sta(j, i + 1, m)) cycle
                        e = e + 1
                        ew%il(e) = i
                        ew%ib(e) = m
                        ew%ia(e) = j
                        ew%left_stable(e) = sta(j, i, m)
                    end do
                end do
            end do
            allocate (res%edge_l(na, max(nl - 1, 1), nb))
            res%edge_l = 0.0_dp
            res%n_bisection_points = 0
            if (ne > 0) then
                call fill_task(d, edges_payload(ew), ew)
                call sweep_run(ew, trim(DESIGN_STAGES(2)), d%path, ckpt(2), &
                               plabel('band edges'), ne, 2, vals, st, options, rep, &
                               payload=edges_payload(ew), deck_text=d%text)
                call add(rep)
                if (st%code /= STATUS_OK) exit run
                do e = 1, ne
                    res%edge_l(ew%ia(e), ew%il(e), ew%ib(e)) = vals(1, e)
                end do
                res%n_bisection_points = nint(sum(vals(2, :)))
            end if

            ! 3. the precision of every candidate
            call fill_task(d, [real(dp) ::], pw)
            call sweep_run(pw, trim(DESIGN_STAGES(3)), d%path, ckpt(3), plabel('precision'), &
                           nl*nb, 3, vals, st, options, rep, deck_text=d%text)
            call add(rep)
            if (st%code /= STATUS_OK) exit run
            res%period_s = reshape(vals(1, :), [nl, nb])
            res%u_rel = reshape(vals(2, :), [nl, nb])
            res%linear_error = reshape(vals(3, :), [nl, nb])

            call assemble(res, sta)
        end block run
        ! (a stage not yet begun when the run was stopped has no checkpoint: no news)
        if (all%resumed > 0 .and. all%note == 'no checkpoint to resume') all%note = ''
        if (present(stat)) stat = st
        if (present(report)) report = all

    contains

        !> The progress label of one stage.
        function plabel(what) result(s)
            character(len=*), intent(in) :: what
            character(len=:), allocatable :: s
            s = ''
            if (len(label) > 0) s = label//' ('//what//')'
        end function plabel

        !> The checkpoint of stage k ('' without outdir).
        function ckpt(k) result(p)
            integer, intent(in) :: k
            character(len=:), allocatable :: p
            p = ''
            if (present(outdir)) p = checkpoint_path(outdir, d%name, trim(DESIGN_STAGES(k)))
        end function ckpt

        !> Sum up a stage's report.
        subroutine add(r)
            type(sweep_report_t), intent(in) :: r
            all%ranks = r%ranks
            all%threads = r%threads
            all%resumed = all%resumed + r%resumed
            all%rejected = all%rejected + r%rejected
            all%checkpoints = all%checkpoints + r%checkpoints
            all%requests = all%requests + r%requests
            all%wall_seconds = all%wall_seconds + r%wall_seconds
            all%serve_seconds = all%serve_seconds + r%serve_seconds
            if (len(all%note) == 0 .and. allocated(r%note)) all%note = r%note
            if (len(all%warning) == 0 .and. allocated(r%warning)) all%warning = r%warning
            res%wall_seconds = all%wall_seconds
        end subroutine add

    end procedure design_sweep

    !> The task of one of the design's sweeps, by its name (DESIGN_STAGES), as the other
    !! ranks of an MPI run build it: from the deck, and for the edges from the sweep's
    !! payload (edges_payload); ERR_DECK for another name.
    module procedure design_task
        stat%code = STATUS_OK
        select case (stage)
        case ('design')
            allocate (floquet_work_t :: task)
        case ('design_edges')
            allocate (edge_work_t :: task)
        case ('design_precision')
            allocate (precision_work_t :: task)
        case default
            call set_error(stat, ERR_DECK, 'design: no sweep named '//stage)
            return
        end select
        call fill_task(d, payload, task)
    end procedure design_task

    !> Fill a task of the design's sweeps from the deck (and the edges from payload).
    subroutine fill_task(d, payload, task)
        type(deck_t), intent(in) :: d           !! the deck
        real(dp), intent(in) :: payload(:)      !! the edges' sweep: il, ib, ia, left_stable
        class(sweep_task_t), intent(inout) :: task  !! one of the stages' types
        real(dp), allocatable :: amps(:)
        integer :: ne
        select type (task)
        type is (floquet_work_t)
            task%dr = design_rig_of(d)
            call design_grid(d, task%ls, task%bs, task%bps, task%amps)
        type is (edge_work_t)
            task%dr = design_rig_of(d)
            call design_grid(d, task%ls, task%bs, task%bps, task%amps)
            ne = size(payload)/4
            task%il = nint(payload(1:ne))
            task%ib = nint(payload(ne + 1:2*ne))
            task%ia = nint(payload(2*ne + 1:3*ne))
            task%left_stable = payload(3*ne + 1:4*ne) > 0.5_dp
        type is (precision_work_t)
            task%dr = design_rig_of(d)
            call design_grid(d, task%ls, task%bs, task%bps, amps)
            task%amp = d%design%amplitude_measure
            task%u = design_uncertainties(d)
        end select
    end subroutine fill_task

    !> The edges of the edges' sweep as reals: il, ib, ia, left_stable (1 or 0).
    pure function edges_payload(ew) result(p)
        type(edge_work_t), intent(in) :: ew
        real(dp), allocatable :: p(:)
        p = [real(ew%il, dp), real(ew%ib, dp), real(ew%ia, dp), merge(1.0_dp, 0.0_dp, &
             ew%left_stable)]
    end function edges_payload

    !> The uncertainties of &design as period_inversion's inputs: u_l on each cable, u_b on
    !! b and on b', none on g or the amplitude.
    pure function design_uncertainties(d) result(u)
        type(deck_t), intent(in) :: d
        type(input_u_t) :: u
        u%mass = d%design%u_mass
        u%l = d%design%u_l
        u%l_prime = d%design%u_l
        u%b = d%design%u_b
        u%b_prime = d%design%u_b
        u%g = 0.0_dp
        u%period = d%design%u_period
        u%amplitude = 0.0_dp
    end function design_uncertainties

    !> From the grid's stability st and the refined edges: the unstable bands of each
    !! amplitude, their union and its complement (the stable bands), each candidate's
    !! stability, margin, and the recommendation.
    subroutine assemble(res, st)
        type(design_result_t), intent(inout) :: res
        logical, intent(in) :: st(:, :, :)      !! (amplitude, l, b)
        type(design_band_t), allocatable :: merged(:)
        type(design_band_t) :: tmp
        integer :: na, nl, nb, i, i1, j, m, k, n
        real(dp) :: lo, hi, start, l, best
        na = size(res%amps)
        nl = size(res%ls)
        nb = size(res%bs)
        allocate (res%unstable(0), res%stable_bands(0))
        do m = 1, nb
            do j = 1, na
                i = 1
                do while (i <= nl)
                    if (st(j, i, m)) then
                        i = i + 1
                        cycle
                    end if
                    i1 = i
                    do while (i < nl)
                        if (st(j, i + 1, m)) exit
                        i = i + 1
                    end do
                    lo = res%ls(1)
                    if (i1 > 1) lo = res%edge_l(j, i1 - 1, m)
                    hi = res%ls(nl)
                    if (i < nl) hi = res%edge_l(j, i, m)
                    res%unstable = [res%unstable, design_band_t(m, j, lo, hi)]
                    i = i + 1
                end do
            end do
            ! the union over the amplitudes, sorted by l_from (insertion sort), then merged
            merged = pack(res%unstable, res%unstable%ib == m)
            do k = 2, size(merged)
                n = k
                do while (n > 1)
                    if (merged(n - 1)%l_from <= merged(n)%l_from) exit
                    tmp = merged(n - 1)
                    merged(n - 1) = merged(n)
                    merged(n) = tmp
                    n = n - 1
                end do
            end do
            start = res%ls(1)
            do k = 1, size(merged)
                if (merged(k)%l_from > start) res%stable_bands = [res%stable_bands, &
                    design_band_t(m, 0, start, merged(k)%l_from)]
                start = max(start, merged(k)%l_to)
            end do
            if (start < res%ls(nl)) res%stable_bands = [res%stable_bands, &
                design_band_t(m, 0, start, res%ls(nl))]
        end do

        allocate (res%stable(nl, nb), res%max_modulus(nl, nb), res%margin(nl, nb))
        res%margin = 0.0_dp
        res%found = .false.
        res%n_qualified = 0
        best = huge(1.0_dp)
        do m = 1, nb
            do i = 1, nl
                res%stable(i, m) = all(st(:, i, m))
                if (any(res%modulus(:, i, m) < 0.0_dp)) then
                    res%max_modulus(i, m) = minval(res%modulus(:, i, m))   ! -2 before -1
                else
                    res%max_modulus(i, m) = maxval(res%modulus(:, i, m))
                end if
                if (.not. res%stable(i, m)) cycle
                l = res%ls(i)
                do k = 1, size(res%stable_bands)
                    if (res%stable_bands(k)%ib /= m) cycle
                    if (l >= res%stable_bands(k)%l_from .and. l <= res%stable_bands(k)%l_to) &
                        res%margin(i, m) = min(l - res%stable_bands(k)%l_from, &
                                               res%stable_bands(k)%l_to - l)
                end do
                if (res%margin(i, m) < MARGIN_FRACTION*l .or. res%u_rel(i, m) < 0.0_dp) cycle
                res%n_qualified = res%n_qualified + 1
                if (res%u_rel(i, m) < best) then
                    best = res%u_rel(i, m)
                    res%found = .true.
                    res%il = i
                    res%ib = m
                end if
            end do
        end do
        res%n_stable = count(res%stable)
    end subroutine assemble

    !> Why no candidate qualifies, and the range to try next (one line).
    function no_candidate_message(d, res) result(msg)
        type(deck_t), intent(in) :: d
        type(design_result_t), intent(in) :: res
        character(len=:), allocatable :: msg
        real(dp) :: lo, hi, best_ratio, lmin, lmax, span, wlo, whi, top, bottom
        integer :: k, j, m, i, jmax, kbest
        logical :: ok
        lmin = res%ls(1)
        lmax = res%ls(size(res%ls))
        span = lmax - lmin
        msg = 'design: no candidate qualifies: of the '//itoa(size(res%ls)*size(res%bs))// &
            ' candidates (l = '//num(lmin)//' ... '//num(lmax)
        if (minval(res%bs) < maxval(res%bs)) then
            msg = msg//', b = '//num(minval(res%bs))//' ... '//num(maxval(res%bs))
        else
            msg = msg//', b = '//num(res%bs(1))
        end if
        if (minval(res%bps) < maxval(res%bps)) then
            msg = msg//', b_prime = '//num(minval(res%bps))//' ... '//num(maxval(res%bps))
        else
            msg = msg//', b_prime = '//num(res%bps(1))
        end if
        msg = msg//'), '//itoa(res%n_stable)//' are stable at every amplitude up to '// &
            num(d%design%amplitude_max)//' deg (largest multiplier <= 1 + '// &
            num(DESIGN_TOLERANCE)//')'
        if (res%n_stable > 0) then
            msg = msg//' but none lies '//itoa(nint(100*MARGIN_FRACTION))//'% of its l '// &
                'from the nearest unstable band or end of the range'
            ! the widest stable band (by the ratio of its ends)
            kbest = 1
            best_ratio = 0.0_dp
            do k = 1, size(res%stable_bands)
                if (res%stable_bands(k)%l_to/res%stable_bands(k)%l_from > best_ratio) then
                    best_ratio = res%stable_bands(k)%l_to/res%stable_bands(k)%l_from
                    kbest = k
                end if
            end do
            lo = res%stable_bands(kbest)%l_from
            hi = res%stable_bands(kbest)%l_to
            msg = msg//' (widest stable band l = '//num(lo)//' ... '//num(hi)//')'
            if (hi >= lmax) then
                msg = msg//'; try l_min = '//num(lo)//', l_max = '//num(wider_top(lo))
            else if (lo <= lmin) then
                msg = msg//'; try l_min = '//num(wider_bottom())//', l_max = '//num(hi)
            else
                msg = msg//'; the stable bands are too narrow for the margin: try another '// &
                    'b (b_min, b_max, nb) or lower amplitude_max'
            end if
            return
        end if
        ! none stable: up to which amplitude is some candidate stable?
        jmax = 0
        do j = 1, size(res%amps)
            ok = .false.
            do m = 1, size(res%bs)
                do i = 1, size(res%ls)
                    if (all(res%modulus(1:j, i, m) >= 0.0_dp .and. &
                            res%modulus(1:j, i, m) <= 1.0_dp + DESIGN_TOLERANCE)) ok = .true.
                end do
            end do
            if (.not. ok) exit
            jmax = j
        end do
        ! extend the range towards the end where the worst multiplier is smaller
        bottom = worst(1)
        top = worst(size(res%ls))
        if (top <= bottom) then
            wlo = lmax
            whi = wider_top(lmax)
        else
            wlo = wider_bottom()
            whi = lmin
        end if
        msg = msg//'; try l_min = '//num(wlo)//', l_max = '//num(whi)
        if (jmax > 0) msg = msg//', or lower amplitude_max to '//num(res%amps(jmax))// &
            ' deg (some candidates are stable up to there)'

    contains

        !> The top of a range above l0: twice l_max, or l_max + (l_max - l_min) when more,
        !! within the deck's limit 1e3 b'.
        real(dp) function wider_top(l0)
            real(dp), intent(in) :: l0
            wider_top = min(max(lmax + span, 2.0_dp*lmax), 1.0e3_dp*d%suspension%b_prime)
            if (wider_top <= l0) wider_top = 2.0_dp*l0
        end function wider_top

        !> The bottom of a range below l_min: half l_min, at least 1e-3 b'.
        real(dp) function wider_bottom()
            wider_bottom = max(0.5_dp*lmin, 1.0e-3_dp*d%suspension%b_prime)
        end function wider_bottom

        !> The worst multiplier over the amplitudes and b at l index i (sentinels: huge).
        real(dp) function worst(i)
            integer, intent(in) :: i
            worst = maxval(merge(res%modulus(:, i, :), huge(1.0_dp), &
                                 res%modulus(:, i, :) >= 0.0_dp))
        end function worst

    end function no_candidate_message

    !> The analysis `design` of a deck: the sweeps (design_sweep, checkpointed in
    !! outdir), then OUTDIR/NAME.design, or, when no candidate qualifies, ERR_MODEL with
    !! the reason and the range to try next (nothing written).  With `files` the file
    !! joins the run's others; without it it is committed at once.
    module procedure run_design
        type(out_files_t), target :: own
        type(out_files_t), pointer :: fs
        integer :: u, ios, i, m, k, na
        character(len=:), allocatable :: path
        character(len=32) :: f
        fs => own
        if (present(files)) fs => files
        call design_ready(d, stat)
        if (stat%code /= STATUS_OK) return
        call design_sweep(d, res, d%name//': design', stat, outdir, options, report)
        if (stat%code /= STATUS_OK) return
        if (.not. res%found) then
            call set_error(stat, ERR_MODEL, no_candidate_message(d, res))
            ! the failure would repeat: the sweeps' checkpoints go (as a failed point's)
            do k = 1, size(DESIGN_STAGES)
                call remove_file(checkpoint_path(outdir, d%name, trim(DESIGN_STAGES(k))))
            end do
            return
        end if
        na = size(res%amps)
        path = outdir//'/'//d%name//'.design'
        call fs%open(path, u, stat)
        if (stat%code /= STATUS_OK) return
        i = res%il
        m = res%ib
        write (u, '(a)', iostat=ios) '# bifilar rig design: '//trim(d%scene%title)
        call put('# candidates: l = l'' and b in deck units; Floquet stability of pure '// &
            'torsion at the amplitudes j amplitude_max/n_amplitudes (deg), stable where the '// &
            'largest multiplier is <= 1 + tolerance at every amplitude; band edges bisected '// &
            'in l to edge_rtol l')
        call put('# precision: one period measured at amplitude_measure, I1 inverted from '// &
            'the exact period, first-order (GUM) budget with u_mass, u_l (each cable), u_b '// &
            '(b and b''), u_period (s); none on g or the amplitude; b'' moves the body''s '// &
            'attachment points symmetrically')
        call put('# recommended: the smallest predicted u(I1)/I1 among candidates stable at '// &
            'every amplitude with stable_margin_l >= margin_fraction l (stable_margin_l: '// &
            'distance to the nearest unstable band or end of the swept range)')
        call deck_echo(d, u, ios)
        call write_kv(u, 'recommended_l', res%ls(i), ios)
        call write_kv(u, 'recommended_b', res%bs(m), ios)
        call write_kv(u, 'recommended_b_prime', res%bps(m), ios)
        call write_kv(u, 'predicted_u_I1_rel', res%u_rel(i, m), ios)
        call write_kv(u, 'period_s', res%period_s(i, m), ios)
        call write_kv(u, 'stable_margin_l', res%margin(i, m), ios)
        call write_kv(u, 'max_modulus', res%max_modulus(i, m), ios)
        call write_kv(u, 'linear_error', res%linear_error(i, m), ios)
        call write_kv(u, 'period_amplitude_deg', d%design%amplitude_measure, ios)
        call write_kv(u, 'amplitude_max', d%design%amplitude_max, ios)
        call write_kv(u, 'n_amplitudes', na, ios)
        call write_kv(u, 'tolerance', DESIGN_TOLERANCE, ios)
        call write_kv(u, 'margin_fraction', MARGIN_FRACTION, ios)
        call write_kv(u, 'edge_rtol', EDGE_RTOL, ios)
        call write_kv(u, 'floquet_rtol', d%floquet%rtol, ios)
        call write_kv(u, 'candidates', size(res%ls)*size(res%bs), ios)
        call write_kv(u, 'stable_candidates', res%n_stable, ios)
        call write_kv(u, 'qualified_candidates', res%n_qualified, ios)
        call write_kv(u, 'floquet_points', res%n_grid_points + res%n_bisection_points, ios)
        call write_kv(u, 'band_edges', res%n_edges, ios)
        call write_kv(u, 'failed_points', res%n_failed, ios)
        call put('')
        call put('')
        f = '(8es24.15e3,'//itoa(na)//'es24.15e3)'
        call put('# candidates: l b b_prime stable max_modulus u_I1_rel period linear_error, '// &
            'then '// &
            'the largest multiplier at each amplitude (stable: 1 at every amplitude, else 0; '// &
            'period in s at amplitude_measure; -1 where pure torsion is not possible, -2 where '// &
            'the analysis failed)')
        call put('# l b b_prime stable max_modulus u_I1_rel period linear_error'//amp_names())
        do m = 1, size(res%bs)
            if (m > 1) call put('')
            do i = 1, size(res%ls)
                if (ios == 0) write (u, f, iostat=ios) res%ls(i), res%bs(m), res%bps(m), &
                    merge(1.0_dp, 0.0_dp, res%stable(i, m)), res%max_modulus(i, m), &
                    res%u_rel(i, m), res%period_s(i, m), res%linear_error(i, m), &
                    res%modulus(:, i, m)
            end do
        end do
        call put('')
        call put('')
        call put('# stable bands (stable at every amplitude up to amplitude_max), for each b '// &
            'and b_prime: l_from l_to')
        do m = 1, size(res%bs)
            if (m > 1) call put('')
            call put('# b = '//sci(res%bs(m), 15)//', b_prime = '//sci(res%bps(m), 15))
            do k = 1, size(res%stable_bands)
                if (res%stable_bands(k)%ib == m .and. ios == 0) write (u, '(2es24.15e3)', &
                    iostat=ios) res%stable_bands(k)%l_from, res%stable_bands(k)%l_to
            end do
        end do
        call put('')
        call put('')
        call put('# unstable bands of each amplitude (or where pure torsion is not possible): '// &
            'b b_prime amplitude l_from l_to')
        do k = 1, size(res%unstable)
            if (ios == 0) write (u, '(5es24.15e3)', iostat=ios) res%bs(res%unstable(k)%ib), &
                res%bps(res%unstable(k)%ib), &
                res%amps(res%unstable(k)%ia), res%unstable(k)%l_from, res%unstable(k)%l_to
        end do
        call fs%close(u, ios, stat)
        if (present(files)) return
        if (stat%code == STATUS_OK) call own%commit(stat)
        if (stat%code /= STATUS_OK) call own%discard()

    contains

        !> One line of text, unless a write failed already.
        subroutine put(text)
            character(len=*), intent(in) :: text
            if (ios == 0) write (u, '(a)', iostat=ios) text
        end subroutine put

        !> The names of the per-amplitude columns: ' modulus_at_8.333333 ...'.
        function amp_names() result(s)
            character(len=:), allocatable :: s
            integer :: j
            s = ''
            do j = 1, na
                s = s//' modulus_at_'//short_number(res%amps(j))
            end do
        end function amp_names

    end procedure run_design

    !> A number for messages: 4 significant digits without trailing zeros, plain from 1e-3
    !! to 1e5 (0.13, 1.137, 50), with its exponent outside (text's sci).
    function num(x) result(s)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: s
        integer :: nd, ie
        if (.not. (abs(x) >= 1.0e-3_dp .and. abs(x) < 1.0e5_dp)) then
            s = sci(x, 3)
            ie = index(s, 'E')
            if (ie > 2) then
                do while (s(ie - 1:ie - 1) == '0')
                    s = s(1:ie - 2)//s(ie:)
                    ie = ie - 1
                end do
                if (s(ie - 1:ie - 1) == '.') s = s(1:ie - 2)//s(ie:)
            end if
            if (x == 0.0_dp) s = '0'
            return
        end if
        nd = max(0, 3 - floor(log10(abs(x))))
        s = fixed(x, nd)
        if (index(s, '.') > 0) then
            do while (s(len(s):len(s)) == '0')
                s = s(1:len(s) - 1)
            end do
            if (s(len(s):len(s)) == '.') s = s(1:len(s) - 1)
        end if
    end function num

    !> A number for a column name: the shortest of f0.1 ... f0.6 that is exact to 1e-9.
    pure function short_number(x) result(s)
        real(dp), intent(in) :: x
        character(len=:), allocatable :: s
        integer :: nd
        do nd = 0, 5
            if (abs(real(nint(x*10.0_dp**nd), dp)/10.0_dp**nd - x) <= 1.0e-9_dp*max(1.0_dp, &
                abs(x))) exit
        end do
        s = fixed(x, nd)
        if (s(len(s):len(s)) == '.') s = s(1:len(s) - 1)
    end function short_number

    !> The preconditions of design: design_ready, and no &damping (undamped_ready).
    module procedure design_analysis_ready
        call unused(self)
        call design_ready(d, stat)
        if (stat%code == STATUS_OK) call undamped_ready(d, stat)
    end procedure design_analysis_ready

    !> The run (run_design into the run's files; its sweeps' warning kept).
    module procedure design_analysis_run
        call run_design(d, outdir, self%res, stat, files=files, options=options, &
                        report=self%rep)
        call self%add_report_warning(self%rep)
    end procedure design_analysis_run

    !> ' design N candidates x N amplitudes, N stable, recommended l = ..., b = ...,
    !! b_prime = ..., u(I1)/I1 = ..., T s[ on N ranks][, N failed points][resume];'
    module procedure design_summary
        call unused(d)
        associate (dr => self%res)
            s = ' design '//itoa(size(dr%ls)*size(dr%bs))//' candidates x '// &
                itoa(size(dr%amps))//' amplitudes, '//itoa(dr%n_stable)//' stable, '// &
                'recommended l = '//sci(dr%ls(dr%il), 4)//', b = '//sci(dr%bs(dr%ib), 4)// &
                ', b_prime = '//sci(dr%bps(dr%ib), 4)// &
                ', u(I1)/I1 = '//sci(dr%u_rel(dr%il, dr%ib), 2)//', '// &
                fixed(dr%wall_seconds, 2)//' s'//ranks_note(self%rep)
            if (dr%n_failed > 0) s = s//', '//itoa(dr%n_failed)//' failed points'
        end associate
        s = s//resume_note(self%rep)//';'
    end procedure design_summary

    !> The task of one of its sweeps on the other ranks of an MPI run (design_task).
    module procedure design_sweep_task
        call unused(self)
        call design_task(sweep, d, payload, task, stat)
    end procedure design_sweep_task

end submodule design_impl
