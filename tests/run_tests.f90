!> The test runner: `run_tests BIFILAR_EXE [FILTER]` runs every suite (or those whose name
!! contains FILTER) and ends with the line "N passed, N failed"; exit status 1 on failure.
program run_tests
    use testing, only: tester_t
    use test_lsoda, only: run_lsoda_tests
    use test_deck, only: run_deck_tests
    use test_model, only: run_model_tests
    use test_floquet, only: run_floquet_tests
    use test_extreme, only: run_extreme_tests
    use test_work_precision, only: run_work_precision_tests
    use test_elastic, only: run_elastic_tests
    use test_elastic_jac, only: run_elastic_jac_tests
    use test_radau, only: run_radau_tests
    use test_elastic_radau, only: run_elastic_radau_tests
    use test_robust, only: run_robust_tests
    use test_fast_format, only: run_fast_format_tests
    use test_columns, only: run_columns_tests
    use test_period, only: run_period_tests
    use test_design, only: run_design_tests
    use test_sweep, only: run_sweep_tests
    use test_identify, only: run_identify_tests
    implicit none
    type(tester_t) :: t
    character(len=1024) :: exe, filter
    exe = 'bin/bifilar'
    if (command_argument_count() >= 1) call get_command_argument(1, exe)
    if (command_argument_count() >= 2) then
        call get_command_argument(2, filter)
        t%only = trim(filter)
    end if
    call run_lsoda_tests(t)
    call run_deck_tests(t)
    call run_model_tests(t, trim(exe))
    call run_floquet_tests(t, trim(exe))
    call run_extreme_tests(t, trim(exe))
    call run_work_precision_tests(t, trim(exe))
    call run_elastic_tests(t)
    call run_elastic_jac_tests(t)
    call run_radau_tests(t)
    call run_elastic_radau_tests(t)
    call run_robust_tests(t, trim(exe))
    call run_fast_format_tests(t)
    call run_columns_tests(t, trim(exe))
    call run_period_tests(t)
    call run_design_tests(t, trim(exe))
    call run_sweep_tests(t, trim(exe))
    call run_identify_tests(t, trim(exe))
    if (.not. t%summary()) error stop 1
end program run_tests
