!> Work-precision of the paper's simulation scenes (make bench): for each deck the
!! analysis of module work_precision (files into build/bench) and one compact line per deck:
!! agreement of the reference with RK4 + Richardson, then the largest angle error and the
!! CPU milliseconds per solve of LSODA at rtol 1e-4, 1e-6, 1e-8, 1e-10, 1e-12, and of
!! fixed-step RK4 at h = dtau_out/8.
program bench_wp
    use kinds, only: dp
    use status, only: status_t
    use deck, only: deck_t, read_deck
    use work_precision, only: run_work_precision, wp_result_t
    implicit none
    character(len=20), parameter :: scenes(4) = [character(len=20) :: 'cylinder_l180', &
        'cylinder_l195', 'triangle_plate', 'cylinder_torsion']
    integer, parameter :: pick(5) = [2, 4, 6, 8, 10]
    type(deck_t) :: d
    type(status_t) :: st
    type(wp_result_t) :: res
    integer :: k, j
    character(len=200) :: line
    call execute_command_line('mkdir -p build/bench')
    write (*, '(a)') 'work-precision of the paper scenes, tau = 0 ... 60 (files in build/bench): '// &
        'largest angle error (rad) / CPU ms per solve'
    write (*, '(a16,a10,6a19)') 'deck', 'ref agree', 'LSODA 1e-4', 'LSODA 1e-6', &
        'LSODA 1e-8', 'LSODA 1e-10', 'LSODA 1e-12', 'RK4 h=dtau/8'
    do k = 1, size(scenes)
        call read_deck('input/'//trim(scenes(k))//'.nml', d, st)
        if (st%code /= 0) error stop 'bench_wp: a paper deck does not read'
        call run_work_precision(d, 'build/bench', res, st, quiet=.true.)
        if (st%code /= 0) then
            write (*, '(a)') trim(scenes(k))//': '//st%msg
            cycle
        end if
        write (line, '(a16,es10.1)') trim(scenes(k)), max(res%ref_agreement_theta, &
                                                          res%ref_agreement_q)
        do j = 1, size(pick)
            write (line(len_trim(line) + 1:), '(es10.1,a,f7.2)') &
                res%lsoda(pick(j))%error_theta, ' /', 1.0e3_dp*res%lsoda(pick(j))%cpu_seconds
        end do
        write (line(len_trim(line) + 1:), '(es10.1,a,f7.2)') res%rk4(4)%error_theta, ' /', &
            1.0e3_dp*res%rk4(4)%cpu_seconds
        write (*, '(a)') trim(line)
    end do
end program bench_wp
