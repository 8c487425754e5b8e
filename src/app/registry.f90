!> The registry of analyses (submodule of driver): every analysis of the program, one line
!! each, in the order of the deck's summary line.  The driver runs them in this order too,
!! except that those whose runs_first is true (chart, design: their sweeps stage no file)
!! run before the others.  Adding an analysis: its two files in src/analyses/ (a type
!! extending analysis_t, module analysis_base), its word in ANALYSES_ALLOWED
!! (deck/analysis_groups.f90), and here its `use` and its line.  Suite graph checks that
!! the words of the registry and of ANALYSES_ALLOWED are the same and that no file or
!! sweep belongs to two analyses.
submodule (driver) registry
    use analysis_base, only: analysis_t
    use work_precision, only: work_precision_analysis_t
    use stability, only: floquet_analysis_t, chart_analysis_t
    use design, only: design_analysis_t
    use identify, only: identify_analysis_t
    use calibrate, only: calibrate_analysis_t
    use tensor, only: tensor_analysis_t
    use simulate, only: simulate_analysis_t
    implicit none

contains

    module procedure analysis_registry
        allocate (reg(0))
        call add(work_precision_analysis_t())
        call add(floquet_analysis_t())
        call add(chart_analysis_t())
        call add(design_analysis_t())
        call add(identify_analysis_t())
        call add(calibrate_analysis_t())
        call add(tensor_analysis_t())
        call add(simulate_analysis_t())
    contains
        !> The next analysis of the registry.
        subroutine add(a)
            class(analysis_t), intent(in) :: a      !! a fresh object of the analysis
            type(analysis_slot_t), allocatable :: grown(:)
            integer :: k
            allocate (grown(size(reg) + 1))
            do k = 1, size(reg)
                call move_alloc(reg(k)%a, grown(k)%a)
            end do
            allocate (grown(size(grown))%a, source=a)
            call move_alloc(grown, reg)
        end subroutine add
    end procedure analysis_registry

end submodule registry
