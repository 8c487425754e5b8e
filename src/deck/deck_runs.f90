!> What the runs take from a deck, for the analyses: the rig (rig_of), its start
!! (start_of), the accuracy and integrator of its runs (accuracy_of, method_of), the output
!! grid (output_times), the inputs of a budget (deck_inputs), the record of a measurement
!! (read_record, record_format_of, record_file; its releases are read into the measurement's
!! model by module measurement_read), and the preconditions several analyses share: the
!! deck's scene can be run (scene_ready: simulate, work_precision), its torsion is undamped
!! (undamped_ready: floquet, chart, design).  Each
!! hands the deck's groups to the procedure of the layer below that takes them (the generic
!! names rig_of, start_of, method_of, accuracy_of, output_times and deck_inputs also take
!! the groups themselves).
module deck_runs
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK
    use text, only: sci
    use deck, only: deck_t
    use rig, only: rig_t, start_t, accuracy_t, rig_of, start_of, method_of, accuracy_of, &
        output_times, make_pendulum, start_state
    use bifilar_model, only: NSTATE
    use elastic_model, only: elastic_t, elastic_start, ELASTIC_NSTATE
    use inputs, only: input_t, deck_inputs
    use records, only: record_t, record_format_t, record_format, read_record_file
    use measure_groups, only: parse_axes
    implicit none
    private

    public :: rig_of, start_of, method_of, accuracy_of, output_times, deck_inputs
    public :: read_record, record_format_of, record_file
    public :: scene_ready, undamped_ready

    interface rig_of
        module procedure deck_rig
    end interface rig_of
    interface start_of
        module procedure deck_start
    end interface start_of
    interface method_of
        module procedure deck_method
    end interface method_of
    interface accuracy_of
        module procedure deck_accuracy
    end interface accuracy_of
    interface output_times
        module procedure deck_output_times
    end interface output_times
    interface deck_inputs
        module procedure deck_budget_inputs
    end interface deck_inputs

contains

    !> The rig of a deck (&suspension, &body, &damping, &cables).
    pure function deck_rig(d) result(rg)
        type(deck_t), intent(in) :: d
        type(rig_t) :: rg
        rg = rig_of(d%suspension, d%body, d%damping, d%cables)
    end function deck_rig

    !> The start of a deck (&start).
    pure function deck_start(d) result(st)
        type(deck_t), intent(in) :: d
        type(start_t) :: st
        st = start_of(d%start)
    end function deck_start

    !> The integrator of a deck's runs (&integration method, &scene model).
    pure integer function deck_method(d)
        type(deck_t), intent(in) :: d
        deck_method = method_of(d%integration, d%scene%model)
    end function deck_method

    !> The accuracy of a deck's runs (&integration, &scene model).
    pure function deck_accuracy(d) result(acc)
        type(deck_t), intent(in) :: d
        type(accuracy_t) :: acc
        acc = accuracy_of(d%integration, d%scene%model)
    end function deck_accuracy

    !> The output grid of a deck's run (&integration tau_end, dtau_out).
    pure subroutine deck_output_times(d, times)
        type(deck_t), intent(in) :: d
        real(dp), allocatable, intent(out) :: times(:)  !! (0:nout)
        call output_times(d%integration, times)
    end subroutine deck_output_times

    !> The inputs of a deck's budget (module inputs), with the release amplitude when
    !! `with_amplitude` (a record fit that holds it).
    pure function deck_budget_inputs(d, with_amplitude) result(x)
        type(deck_t), intent(in) :: d
        logical, intent(in) :: with_amplitude
        type(input_t), allocatable :: x(:)
        x = deck_inputs(d%suspension, d%body, d%measurement, d%start, with_amplitude)
    end function deck_budget_inputs

    !> How the deck's records are to be read (&measurement record_columns by number or
    !! name, record_units or quantity, record_frame_rate; the rig's sqrt(g/b') for the
    !! range of a rate).
    pure function record_format_of(d) result(f)
        type(deck_t), intent(in) :: d
        type(record_format_t) :: f
        real(dp) :: axes(3, 3)
        logical :: ok
        f = record_format(d%measurement%record_columns, d%measurement%quantity, &
                          d%measurement%record_units, d%suspension%g, d%suspension%b_prime, &
                          d%measurement%record_column_names, d%measurement%record_frame_rate, &
                          d%measurement%gave('quantity'))
        call parse_axes(d%measurement%record_axes, axes, ok)
        f%down = axes(:, 1)
        f%scale = d%measurement%record_scale
    end function record_format_of

    !> The record file of a deck: &measurement record relative to the deck's folder
    !! (record_path), or as given.
    pure function record_file(d) result(path)
        type(deck_t), intent(in) :: d
        character(len=:), allocatable :: path
        path = trim(d%measurement%record)
        if (allocated(d%measurement%record_path)) path = d%measurement%record_path
    end function record_file

    !> Read and check the record of a deck (&measurement record, relative to the deck's
    !! folder): read_record_file with the deck's format.  ERR_DECK naming the record.
    subroutine read_record(d, rec, stat)
        type(deck_t), intent(in) :: d           !! the deck (record, record_path, format)
        type(record_t), intent(out) :: rec
        type(status_t), intent(out) :: stat     !! ERR_DECK
        call read_record_file(record_file(d), record_format_of(d), rec, stat)
        if (stat%code /= STATUS_OK) stat%msg = '&measurement record = '''// &
            trim(d%measurement%record)//''': '//stat%msg
    end subroutine read_record

    !> The preconditions of analyses = 'simulate' and 'work_precision', checked before any
    !! computing: the cables reach (make_pendulum), the start exists (start_state) and, for
    !! model = 'elastic', no &damping and the elastic start.
    subroutine scene_ready(d, stat)
        type(deck_t), intent(in) :: d           !! the deck
        type(status_t), intent(out) :: stat     !! ERR_DECK, or the start's failure
        type(elastic_t) :: el
        real(dp) :: yc(NSTATE), th0(5), y(ELASTIC_NSTATE)
        call make_pendulum(rig_of(d), el%p, stat)
        if (stat%code /= 0) return
        call start_state(start_of(d), el%p, yc, th0, stat)
        if (stat%code /= 0 .or. trim(d%scene%model) /= 'elastic') return
        if (d%damping%c_v /= 0.0_dp .or. d%damping%c_q /= 0.0_dp) then
            call set_error(stat, ERR_DECK, '&damping c_v = '//sci(d%damping%c_v)//', c_q = '// &
                sci(d%damping%c_q)//': the damping about the vertical is a torque of the '// &
                'paper''s model; allowed: c_v = c_q = 0 with model = ''elastic'' (its cables '// &
                'have &cables damping), or model = ''kane''')
            return
        end if
        el%stiffness = d%cables%stiffness
        el%damping = d%cables%damping
        call elastic_start(el, yc, y, stat)
        if (stat%code /= 0) stat%msg = 'elastic start: '//stat%msg
    end subroutine scene_ready

    !> The preconditions of analyses = 'floquet', 'chart' and 'design': no &damping (they
    !! analyse the periodic torsion of the undamped model; a damped torsion is not periodic).
    subroutine undamped_ready(d, stat)
        type(deck_t), intent(in) :: d               !! the deck
        type(status_t), intent(out) :: stat         !! ERR_DECK
        stat%code = STATUS_OK
        if (d%damping%c_v == 0.0_dp .and. d%damping%c_q == 0.0_dp) return
        stat%code = ERR_DECK
        stat%msg = '&damping c_v = '//sci(d%damping%c_v)//', c_q = '//sci(d%damping%c_q)// &
            ': floquet, chart and design analyse the periodic torsion of the undamped model (a '// &
            'damped torsion is not periodic); allowed: c_v = c_q = 0 with floquet, chart or design'
    end subroutine undamped_ready

end module deck_runs
