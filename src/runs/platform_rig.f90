!> The multifilar platform of a deck: the model's platform_t made from the deck's groups of
!! the rig (&suspension cables >= 3, &body, &damping), which model runs it, and the checks
!! a run needs before it starts (platform_case: the chart, the rest pose, its stability).
!!
!! The deck's platform.  A regular polygon (radius, radius_prime, l: regular_platform) or
!! any n cables point by point (support_points, body_points, lengths: general_platform),
!! in the deck's units (time in the unit g implies: seconds in SI).  The body's mass
!! centre at cg_offset = (x, y) in the body's frame, cg_depth below the plane of the
!! attachments (their mean height, point by point).  Its inertia as the bifilar's: the
!! principal moments inertia(1:3) about the principal axes whose components are the rows
!! of btilde, in the axes (e1, e2, e3) = (z, x, y) of the body's frame: e1 vertical when
!! the body hangs level, so that inertia(1) is the moment about the vertical that the
!! torsion measures, as on the bifilar; J_B = P btilde^T diag(inertia) btilde P^T with P
!! the permutation from (e1, e2, e3) to (x, y, z).  The damping torque about the vertical
!! of &damping (c_v, c_q, in deck units).
!!
!! The model.  n = 3 (and n = 2, which a deck runs as the paper's bifilar) with
!! inextensible cables by default (&scene model = 'kane'); elastic cables with
!! model = 'elastic'; n >= 4 always elastic: with inextensible cables it is statically
!! indeterminate (uses_elastic).  For n <= 3 elastic cables have the given lengths loaded
!! at the start (platform_elastic's pe_from_inextensible); for n >= 4 the given lengths are
!! the natural lengths.
module platform_rig
    use kinds, only: dp, deg
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK, ERR_MODEL
    use text, only: sci, itoa, rshort
    use rig_groups, only: suspension_group_t, body_group_t, damping_group_t, cables_group_t
    use platform_geometry, only: platform_t, regular_platform, general_platform, &
                                 platform_prepare, platform_inertia
    use platform_model, only: check_platform, platform_start, rest_pose, platform_evaluate, &
                              platform_motion_t
    use platform_elastic, only: platform_elastic_t, pe_rest_pose, pe_linearise, pe_start, &
                                pe_from_inextensible, pe_evaluate, pe_motion_t, PE_NSTATE
    implicit none
    private

    !> A platform ready to run: its rig prepared with the rest pose as the reference (the
    !! inextensible model's, or the elastic one's), and the elastic model when it runs
    !! elastic cables.
    type, public :: platform_case_t
        type(platform_t) :: pl                  !! the rig, prepared, rest pose in q_ref
        logical :: elastic = .false.            !! elastic cables (uses_elastic)
        type(platform_elastic_t) :: el          !! the elastic model (elastic)
        real(dp) :: q_rest(6) = 0.0_dp          !! the elastic rest (Q; n >= 4)
    end type platform_case_t

    public :: is_platform, uses_elastic, platform_inertia, platform_of
    public :: platform_case, platform_case_start

contains

    !> True when the suspension is a platform (cables >= 3; two cables are the bifilar).
    pure logical function is_platform(sus)
        type(suspension_group_t), intent(in) :: sus
        is_platform = sus%cables > 2
    end function is_platform

    !> True when a platform of n cables runs elastic cables: model = 'elastic', or n >= 4
    !! (statically indeterminate with inextensible cables).
    pure logical function uses_elastic(n, model)
        integer, intent(in) :: n                !! cables
        character(len=*), intent(in) :: model   !! &scene model ('kane', 'elastic')
        uses_elastic = n >= 4 .or. trim(adjustl(model)) == 'elastic'
    end function uses_elastic

    !> The platform of the deck's groups (checked: cables >= 3), in deck units; not yet
    !! prepared (platform_case).
    pure function platform_of(sus, bod, dmp) result(pl)
        type(suspension_group_t), intent(in) :: sus
        type(body_group_t), intent(in) :: bod
        type(damping_group_t), intent(in) :: dmp
        type(platform_t) :: pl
        integer :: n
        n = sus%cables
        if (sus%pointwise()) then
            pl = general_platform(n, sus%support_points(:, 1:n), sus%body_points(:, 1:n), &
                                  sus%lengths(1:n), bod%mass, &
                                  platform_inertia(bod%inertia, bod%btilde), &
                                  [bod%cg_offset, bod%cg_offset_y], bod%cg_depth, sus%g)
        else
            pl = regular_platform(n, sus%radius, sus%radius_prime, sus%l, bod%mass, &
                                  platform_inertia(bod%inertia, bod%btilde), &
                                  [bod%cg_offset, bod%cg_offset_y], bod%cg_depth, sus%g)
        end if
        pl%c_v = dmp%c_v
        pl%c_q = dmp%c_q
    end function platform_of

    !> A platform ready to run: prepared, its rest pose found and stable.  Inextensible
    !! (n <= 3): check_platform (ERR_DECK for a bad rig, a cable slack at rest; ERR_MODEL
    !! naming the tipping height when the body tips over).  Elastic: for n <= 3 the same
    !! checks of the inextensible rig, whose lengths the elastic cables take loaded; for
    !! n >= 4 the elastic rest pose (pe_rest_pose; ERR_DECK when a cable is slack at rest)
    !! and its stability (pe_linearise; ERR_MODEL naming the cg_depth at which it tips,
    !! found by bisection).  A cable slack at rest of a body the centred one would not
    !! slacken: ERR_DECK naming cg_offset and the offset at which that cable goes slack
    !! (offset_limit), for any n.
    subroutine platform_case(pl, elastic, stiffness, damping, pc, stat)
        type(platform_t), intent(in) :: pl      !! the deck's platform (platform_of)
        logical, intent(in) :: elastic          !! elastic cables (uses_elastic)
        real(dp), intent(in) :: stiffness       !! &cables stiffness: EA/(m g)
        real(dp), intent(in) :: damping         !! &cables damping ratio
        type(platform_case_t), intent(out) :: pc
        type(status_t), intent(out) :: stat
        real(dp) :: w2(6), depth, zbar
        logical :: found
        pc%pl = pl
        pc%elastic = elastic
        if (pl%n <= 3) then
            call check_platform(pc%pl, stat)
            if (stat%code == ERR_DECK) call offset_limit(pl, stiffness, damping, stat)
            if (stat%code /= STATUS_OK) return
        end if
        if (.not. elastic) return
        pc%el%pl = pc%pl
        pc%el%stiffness = stiffness
        pc%el%damping = damping
        if (pl%n <= 3) return
        call platform_prepare(pc%el%pl, stat)
        if (stat%code /= STATUS_OK) return
        call pe_rest_pose(pc%el, pc%q_rest, stat)
        if (stat%code == ERR_DECK) call offset_limit(pl, stiffness, damping, stat)
        if (stat%code /= STATUS_OK) return
        call pe_linearise(pc%el, pc%q_rest, w2, stat)
        if (stat%code /= STATUS_OK) return
        if (w2(1) > 0.0_dp) then
            pc%pl = pc%el%pl
            return
        end if
        zbar = sum(pl%body(3, 1:pl%n))/pl%n
        call elastic_tipping(pc%el, depth, found)
        if (found) then
            call set_error(stat, ERR_MODEL, 'platform cg_depth = '//sci(zbar - pl%cg(3))// &
                           ': the body tips over (its rest pose is unstable) with the mass '// &
                           'centre above cg_depth = '//sci(depth)//'; lower it')
        else
            call set_error(stat, ERR_MODEL, 'platform: the rest pose is unstable')
        end if
    end subroutine platform_case

    !> A rig refused at rest (stat ERR_DECK) whose body hangs off the attachments' centre c
    !! (the mean of the body points in x, y): when the centred body (mass centre at c) hangs
    !! with every cable taut, the mass centre's offset is the cause, and stat says so with
    !! the limit: the offset s (cg - c) at which a cable first goes slack, s in (0, 1) by
    !! bisection to 1e-9 on the rest pose with every cable taut (the inextensible model's
    !! for n <= 3, the elastic one's for n >= 4), the cable the one of least tension there.
    !! Otherwise stat is left as it is.
    subroutine offset_limit(pl, stiffness, damping, stat)
        type(platform_t), intent(in) :: pl      !! the deck's platform (platform_of)
        real(dp), intent(in) :: stiffness       !! &cables stiffness: EA/(m g)
        real(dp), intent(in) :: damping         !! &cables damping ratio
        type(status_t), intent(inout) :: stat
        real(dp) :: c(2), off(2), lo, hi, sm, lim(2)
        integer :: i, k, kk
        c = sum(pl%body(1:2, 1:pl%n), dim=2)/pl%n
        off = pl%cg(1:2) - c
        if (.not. (norm2(off) > 0.0_dp)) return
        if (.not. taut_at(0.0_dp, k)) return
        if (taut_at(1.0_dp, kk)) return
        lo = 0.0_dp
        hi = 1.0_dp
        do i = 1, 60
            if (hi - lo <= 1.0e-9_dp) exit
            sm = 0.5_dp*(lo + hi)
            if (taut_at(sm, kk)) then
                lo = sm
                k = kk
            else
                hi = sm
            end if
        end do
        lim = c + lo*off
        call set_error(stat, ERR_DECK, 'platform cg_offset = '//rshort(pl%cg(1))//', '// &
            rshort(pl%cg(2))//': cable '//itoa(k)//' is slack at rest: the cables hold the '// &
            'mass centre up to '//sci(lo*norm2(off), 4)//' from the attachments'' centre ('// &
            pair(c)//') in this direction, and it is '//sci(norm2(off), 4)//' (cable '// &
            itoa(k)//' slack beyond cg_offset = '//pair(lim)//'); allowed: cg_offset '// &
            'nearer the centre than that')
    contains
        !> Every cable taut at rest with the mass centre at c + s off; k the cable of least
        !! tension there.
        logical function taut_at(s, k)
            real(dp), intent(in) :: s
            integer, intent(out) :: k
            type(platform_t) :: p
            type(platform_elastic_t) :: e
            type(platform_motion_t) :: mo
            type(pe_motion_t) :: me
            type(status_t) :: st
            real(dp) :: y(PE_NSTATE), q(6)
            integer :: nf
            taut_at = .false.
            k = 1
            p = pl
            p%cg(1:2) = c + s*off
            if (p%n <= 3) then
                call platform_prepare(p, st)
                if (st%code == STATUS_OK) call rest_pose(p, st)
                if (st%code /= STATUS_OK) return
                nf = p%nf
                y = 0.0_dp
                y(1:nf) = p%q_ref(p%free(1:nf))
                call platform_evaluate(p, y(1:2*nf), mo, st)
                if (st%code /= STATUS_OK) return
                k = p%master(minloc(mo%tension(1:p%nd), 1))
                taut_at = mo%tension(minloc(mo%tension(1:p%nd), 1)) > 0.0_dp
            else
                e%pl = p
                e%stiffness = stiffness
                e%damping = damping
                call platform_prepare(e%pl, st)
                if (st%code == STATUS_OK) call pe_rest_pose(e, q, st)
                if (st%code /= STATUS_OK) return
                y = 0.0_dp
                y(1:6) = q
                call pe_evaluate(e, y, me, st)
                if (st%code /= STATUS_OK) return
                k = minloc(me%tension(1:p%n), 1)
                taut_at = me%tension(k) > 0.0_dp
            end if
        end function taut_at
        !> x, y (4 digits; 0 within roundoff of the rig's size)
        function pair(v) result(txt)
            real(dp), intent(in) :: v(2)
            character(len=:), allocatable :: txt
            txt = one(v(1))//', '//one(v(2))
        end function pair
        function one(x) result(txt)
            real(dp), intent(in) :: x
            character(len=:), allocatable :: txt
            txt = '0'
            if (abs(x) > 1.0e-12_dp*maxval(abs(pl%body(1:2, 1:pl%n)))) txt = sci(x, 4)
        end function one
    end subroutine offset_limit

    !> The cg_depth at which the elastic platform's rest pose turns unstable (the smallest
    !! eigenvalue of its linearised model through 0), by bisection between the depth given
    !! (unstable) and one below it that is stable, to 1e-9 of the rig's size; found =
    !! .false. when no depth down to 1000 sizes below is stable.
    subroutine elastic_tipping(el, depth, found)
        type(platform_elastic_t), intent(in) :: el  !! unstable at its cg
        real(dp), intent(out) :: depth
        logical, intent(out) :: found
        real(dp) :: zbar, d0, dst, dun, step, dm
        integer :: i
        found = .false.
        zbar = sum(el%pl%body(3, 1:el%pl%n))/el%pl%n
        d0 = zbar - el%pl%cg(3)
        depth = d0
        step = 0.25_dp*el%pl%lscale
        dun = d0
        dst = d0
        do i = 1, 40
            dst = d0 + step
            if (stable_at(dst)) exit
            dun = dst
            step = 2.0_dp*step
            if (step > 1000.0_dp*el%pl%lscale) return
        end do
        do i = 1, 100
            if (abs(dst - dun) <= 1.0e-9_dp*el%pl%lscale) exit
            dm = 0.5_dp*(dst + dun)
            if (stable_at(dm)) then
                dst = dm
            else
                dun = dm
            end if
        end do
        depth = 0.5_dp*(dst + dun)
        found = .true.
    contains
        logical function stable_at(d)
            real(dp), intent(in) :: d
            type(platform_elastic_t) :: e
            type(status_t) :: st
            real(dp) :: qr(6), w(6)
            e = el
            e%pl%cg(3) = zbar - d
            stable_at = .false.
            call pe_rest_pose(e, qr, st)
            if (st%code /= STATUS_OK) return
            call pe_linearise(e, qr, w, st)
            if (st%code /= STATUS_OK) return
            stable_at = w(1) > 0.0_dp
        end function stable_at
    end subroutine elastic_tipping

    !> The start of a run: released at rest, turned by amplitude_deg about the vertical
    !! through the mass centre from the rest pose.  Inextensible: y0 = (q_F, q_F') (2 nf);
    !! elastic (12): for n <= 3 the inextensible start with the natural lengths set so that
    !! the cables carry its tensions there (pe_from_inextensible, pc%el changed), for n >= 4
    !! pe_start from the elastic rest.  ERR_DECK when the cables cannot hold the body there.
    subroutine platform_case_start(pc, amplitude_deg, y0, stat)
        type(platform_case_t), intent(inout) :: pc
        real(dp), intent(in) :: amplitude_deg
        real(dp), allocatable, intent(out) :: y0(:)
        type(status_t), intent(out) :: stat
        real(dp) :: yi(8)
        integer :: nf
        if (.not. pc%elastic) then
            nf = pc%pl%nf
            allocate (y0(2*nf))
            call platform_start(pc%pl, amplitude_deg*deg, y0, stat)
            return
        end if
        allocate (y0(PE_NSTATE))
        if (pc%pl%n <= 3) then
            nf = pc%pl%nf
            call platform_start(pc%pl, amplitude_deg*deg, yi(1:2*nf), stat)
            if (stat%code /= STATUS_OK) return
            call pe_from_inextensible(pc%el, yi(1:2*nf), y0, stat)
        else
            call pe_start(pc%el, pc%q_rest, amplitude_deg*deg, y0, stat)
        end if
        if (stat%code == ERR_DECK) return
    end subroutine platform_case_start

end module platform_rig
