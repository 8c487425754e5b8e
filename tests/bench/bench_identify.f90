!> Work units for the identify figures of `make bench` (tests/bench/speed.sh):
!! each mode repeats one unit n times, so that its instruction count is the difference of
!! two runs under `valgrind --tool=callgrind` (n and 0 repetitions) over n, and its CPU time
!! the cpu_time of a run over n.
!!
!!   bench_identify periods N       one inversion of the three periods of
!!                                  input/identify_periods.nml (symmetric rig: exact torsion)
!!   bench_identify periods_asym N  the same periods on that rig with l' = 1.18 m and the mass
!!                                  centre 0.5 mm off (periods of the full model, simulated)
!!   bench_identify record N        the fit of input/identify_record_swing.dat (30 s, 100 Hz,
!!                                  3001 samples) with three parameters, I1 c_v c_q, and its
!!                                  first-order budget (identify_record)
!!   bench_identify record_differences N  the same with &integration sensitivities =
!!                                  'differences' (the Jacobian and the budget's input
!!                                  sensitivities from differences of whole runs)
!!   bench_identify mc N            N Monte Carlo samples from the periods of
!!                                  input/identify_periods.nml (one unit = one sample; OpenMP
!!                                  threads as set, OMP_NUM_THREADS)
!!
!! Prints one line: `MODE units cpu_seconds_per_unit checksum`.
program bench_identify
    use kinds, only: dp
    use status, only: status_t
    use bench_args, only: int_arg, need
    use deck, only: deck_t, read_deck
    use deck_runs, only: rig_of, accuracy_of, read_record, deck_inputs
    use period_inversion, only: input_u_t, period_fit_t, invert_periods, period_monte_carlo
    use identify, only: identify_result_t, identify_record
    use records, only: record_t
    implicit none
    character(len=256) :: mode
    type(deck_t) :: d
    type(status_t) :: st
    type(period_fit_t) :: f
    type(input_u_t) :: u
    type(record_t) :: rec
    type(identify_result_t) :: res
    real(dp) :: t0, t1, sumck, mean, sdev
    integer :: n, k, units
    call get_command_argument(1, mode)
    n = int_arg(2)
    sumck = 0.0_dp
    units = n
    select case (trim(mode))
    case ('periods', 'periods_asym', 'mc')
        call read_deck('input/identify_periods.nml', d, st)
        call need(st, 'bench_identify')
        if (trim(mode) == 'periods_asym') then
            d%suspension%l_prime = 1.18_dp
            d%body%lambda = 0.64_dp
        end if
        associate (m => d%measurement)
            u = input_u_t(period=m%u_period, amplitude=m%u_amplitude, mass=m%u_mass, l=m%u_l, &
                          l_prime=m%u_l_prime, b=m%u_b, b_prime=m%u_b_prime, g=m%u_g)
        end associate
        call cpu_time(t0)
        if (trim(mode) == 'mc') then
            if (n >= 2) then
                call period_monte_carlo(d, rig_of(d), accuracy_of(d), deck_inputs(d, .false.), &
                                        d%measurement%periods(1:3), &
                                        d%measurement%amplitudes(1:3), u, 0.0512_dp, n, &
                                        d%measurement%seed, mean, sdev, st)
                call need(st, 'bench_identify')
                sumck = sdev
            end if
        else
            do k = 1, n
                call invert_periods(rig_of(d), accuracy_of(d), d%measurement%periods(1:3), &
                                    d%measurement%amplitudes(1:3), u, f, st)
                call need(st, 'bench_identify')
                sumck = sumck + f%i1
            end do
        end if
        call cpu_time(t1)
    case ('record', 'record_differences')
        call read_deck('input/identify_record.nml', d, st)
        call need(st, 'bench_identify')
        if (trim(mode) == 'record_differences') d%integration%sensitivities = 'differences'
        d%measurement%estimate = 'I1 c_v c_q'
        d%measurement%monte_carlo = 0
        call read_record(d, rec, st)
        call need(st, 'bench_identify')
        call cpu_time(t0)
        do k = 1, n
            call identify_record(d, rec, res, st)
            call need(st, 'bench_identify')
            sumck = sumck + res%i1
        end do
        call cpu_time(t1)
    case default
        write (*, '(a)') 'usage: bench_identify periods|periods_asym|record|record_differences|mc N'
        stop 1
    end select
    write (*, '(a,1x,i0,es14.5,es24.15)') trim(mode), units, (t1 - t0)/max(1, units), sumck

end program bench_identify
