!> The amplitude limit of analysis tensor, measured: the drift of theta_4's maxima of each
!! hang of a deck's table at given amplitudes, for the true body of the deck (&body inertia
!! and the rows of &body btilde as principal moments and axes in the body frame, as
!! make_record hangs reads them), and each hang's limit (drift <= DRIFT_MAX).
!!
!!   bench_tensor drift DECK A1 [A2 ...]
!!
!! Prints a table: hang, up, the angle between up and the nearest principal axis (degrees),
!! the torsion mode's theta_4 share and the largest other mode's, the drift at each amplitude
!! (DRIFT_CYCLES cycles), the limit in degrees.
program bench_tensor
    use kinds, only: dp, deg
    use status, only: status_t
    use deck, only: deck_t, read_deck
    use deck_runs, only: accuracy_of
    use measurement, only: measurement_t
    use measurement_read, only: read_hangs
    use hang_model, only: tensor_entries, hang_rig, torsion_mode, torsion_mode_t, maxima_drift
    use tensor_fit, only: tensor_problem_t, problem_of, amplitude_limits, DRIFT_MAX, DRIFT_CYCLES
    use rig, only: rig_t
    implicit none
    character(len=256) :: mode, arg
    type(deck_t) :: d
    type(status_t) :: st
    type(measurement_t) :: set
    type(tensor_problem_t) :: prob
    type(rig_t) :: rg
    type(torsion_mode_t) :: md
    real(dp), allocatable :: amps(:), drift(:), limit(:)
    real(dp) :: jt(3, 3), x(6), dr, ad
    integer :: k, h, na, ios
    call get_command_argument(1, mode)
    call get_command_argument(2, arg)
    if (trim(mode) /= 'drift' .or. command_argument_count() < 3) then
        write (*, '(a)') 'usage: bench_tensor drift DECK A1 [A2 ...]'
        error stop 1
    end if
    call read_deck(trim(arg), d, st)
    if (st%code /= 0) then
        write (*, '(a)') st%msg
        error stop 1
    end if
    na = command_argument_count() - 2
    allocate (amps(na))
    do k = 1, na
        call get_command_argument(2 + k, arg)
        read (arg, *, iostat=ios) amps(k)
        if (ios /= 0) error stop 1
    end do
    call read_hangs(d%tensor, d%suspension, d%body, set, st)
    if (st%code /= 0) then
        write (*, '(a)') st%msg
        error stop 1
    end if
    jt = 0.0_dp
    do k = 1, 3
        jt = jt + d%body%inertia(k)*spread(d%body%btilde(k, :), 2, 3)* &
            spread(d%body%btilde(k, :), 1, 3)
    end do
    x = tensor_entries(jt)
    call problem_of(d%tensor, d%suspension, d%body, accuracy_of(d), set, prob)
    allocate (drift(size(prob%rows)), limit(size(prob%hangs)))
    call amplitude_limits(prob, x, drift, limit, st)
    write (*, '(a,es8.1,a,i0,a)') '# drift of theta4''s maxima (over ', DRIFT_MAX, &
        ': refused) in the first ', DRIFT_CYCLES, ' cycles'
    write (*, '(a)', advance='no') '# hang  up                 axis  share  other '
    do k = 1, na
        write (*, '(a,f5.1,a)', advance='no') '  A=', amps(k), '  '
    end do
    write (*, '(a)') '  limit(deg)'
    do h = 1, size(set%releases)
        call hang_rig(d%body%mass, d%suspension%g, set%releases(h)%hang, x, rg, st)
        call torsion_mode(rg, md, st)
        associate (hh => set%releases(h)%hang)
            write (*, '(i5,3f6.2,f6.1,2f7.3)', advance='no') hh%id, hh%up, &
                acos(min(1.0_dp, maxval(abs(matmul(hh%up, transpose(d%body%btilde))))))/deg, &
                md%share, md%next_share
        end associate
        do k = 1, na
            call maxima_drift(rg, prob%acc, amps(k), DRIFT_CYCLES, dr, ad, st)
            if (st%code /= 0) dr = -1.0_dp
            write (*, '(es11.2)', advance='no') dr
        end do
        write (*, '(f10.1)') limit(h)
    end do
end program bench_tensor
