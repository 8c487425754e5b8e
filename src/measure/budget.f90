!> The uncertainty budget of a measurement (GUM, JCGM 100:2008): the standard uncertainties
!! of the inputs and one line of the budget per input, each with its kind.  The types every
!! measurement analysis shares; no computing here.
module budget
    use kinds, only: dp
    implicit none
    private

    !> Standard uncertainties of the inputs (deck units; period in s, amplitude in degrees);
    !! each >= 0, 0 when not known.
    type, public :: input_u_t
        real(dp) :: mass = 0.0_dp, l = 0.0_dp, l_prime = 0.0_dp, b = 0.0_dp, b_prime = 0.0_dp
        real(dp) :: g = 0.0_dp, period = 0.0_dp, amplitude = 0.0_dp
    end type input_u_t

    !> The kinds of a budget's rows: what an input is, so that no code has to read it from
    !! the row's label.
    !! * ROW_INPUT: an input of the rig or the body (mass, a length, g, I2, the mass centre);
    !! * ROW_TIMING: a period's timing (a stopwatch's or a gate's reading of it);
    !! * ROW_AMPLITUDE: an amplitude's reading (a period's, or a record's release);
    !! * ROW_AMPLITUDE_SCALE: the scale an amplitude is read on (a protractor's, a gyro's);
    !! * ROW_DEFINITION: a period's definition (the drift of the maxima of a hang);
    !! * ROW_DIRECTION: how a body was set in a hang (three small rotations);
    !! * ROW_FIT: a fit's residuals (a record's scatter about the model);
    !! * ROW_RELEASE: the scatter of repeated releases (their reproducibility);
    !! * ROW_SESSION: the scatter between sessions of measurement;
    !! * ROW_TARE: a tare's moment subtracted (the empty rig, the holder);
    !! * ROW_ADDED: a known moment added (a calibration mass, an added body);
    !! * ROW_CALIBRATION: a calibration of the rig (a body of known moment).
    integer, parameter, public :: ROW_INPUT = 1, ROW_TIMING = 2, ROW_AMPLITUDE = 3, &
        ROW_AMPLITUDE_SCALE = 4, ROW_DEFINITION = 5, ROW_DIRECTION = 6, ROW_FIT = 7, &
        ROW_RELEASE = 8, ROW_SESSION = 9, ROW_TARE = 10, ROW_ADDED = 11, ROW_CALIBRATION = 12
    integer, parameter, public :: ROW_KINDS = 12
    !> Each kind in words (ROW_KIND_NAMES(kind)).
    character(len=16), parameter, public :: ROW_KIND_NAMES(ROW_KINDS) = [character(len=16) :: &
        'input', 'timing', 'amplitude', 'amplitude_scale', 'definition', 'direction', 'fit', &
        'release', 'session', 'tare', 'added', 'calibration']

    !> One input of a budget: a quantity of the rig, the body or the start with its value
    !! and standard uncertainty (module inputs: which quantities, how each is set on a rig).
    type, public :: input_t
        character(len=16) :: name = ''          !! mass, l, ..., cg_depth, amplitude
        real(dp) :: value = 0.0_dp              !! deck units (amplitude: degrees)
        real(dp) :: u = 0.0_dp                  !! its standard uncertainty
    end type input_t

    !> One line of an uncertainty budget.
    type, public :: budget_row_t
        character(len=24) :: input = ''         !! e.g. mass, l, period(2)
        real(dp) :: value = 0.0_dp              !! the input's value (deck units)
        real(dp) :: u = 0.0_dp                  !! its standard uncertainty
        real(dp) :: sensitivity = 0.0_dp        !! dI1/dx
        real(dp) :: contribution = 0.0_dp       !! |sensitivity| u
        integer :: kind                         !! ROW_*: what the input is
    end type budget_row_t

end module budget
