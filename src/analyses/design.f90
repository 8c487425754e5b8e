!> Rig design (analysis `design`): the suspension that measures I1 best and keeps
!! its torsion stable.
!!
!! Kane & Tseng close their parallelepiped example (after Figs. 13-16) with the advice: to
!! find a satisfactory suspension, "use the stability analysis for various combinations of
!! b and l until one is found that does not lead to a prediction of instability".  This
!! module does that over a grid of candidate rigs, and adds what a measurement engineer
!! weighs next, how precisely each candidate measures I1:
!!
!! * Candidates: l = l' at nl values from l_min to l_max, times the spacing pairs: nb
!!   values of the support's b from b_min to b_max (b_min = b_max = 0, nb = 1: the deck's b)
!!   times nb_prime values of the body's b' from b_prime_min to b_prime_max (likewise), b
!!   fastest; all in deck units.  The body is the deck's; a changed b' moves its two
!!   attachment points symmetrically (the mass centre keeps its depth below CD).
!! * Stability: the Floquet analysis of pure torsion (module floquet, eqs. (45)-(51)) at the
!!   amplitudes a_j = j amplitude_max / n_amplitudes, j = 1 .. n_amplitudes, with &floquet
!!   rtol and segments.  A point is stable when its largest multiplier is at most
!!   1 + DESIGN_TOLERANCE (floquet's STABILITY_MARGIN, 1e-6); a candidate when it is stable
!!   at every amplitude.  For each amplitude and b, where stability changes between two
!!   neighbouring l of the grid, the edge is refined by bisection in l down to a bracket of
!!   EDGE_RTOL l.  The unstable bands of one amplitude run between refined edges (or the
!!   ends of the range); their union over the amplitudes is the unstable set, its
!!   complement in [l_min, l_max] the stable bands.  (A band narrower than the grid's step
!!   can fall between two grid values and go unseen, as in a chart.)
!! * Precision: the period T (s) of the candidate at amplitude_measure (default
!!   min(25, amplitude_max) degrees, whatever the stability range; the exact period of
!!   module period_inversion), measured once: I1 is inverted back from it and its first-order
!!   GUM budget taken by period_budget, the same propagation `identify` uses, with the
!!   uncertainties u_mass, u_l (each cable), u_b (the support spacing b and the body's b',
!!   both measured lengths), u_period, and none on g or the amplitude.  Also the error the
!!   linear formula m g b b' T^2 / (16 pi^2 l) would make at that amplitude.
!! * Recommendation: among candidates stable at every amplitude whose stable_margin_l, the
!!   distance from l to the nearest l not known to be stable (the nearest unstable band, or
!!   an end of the swept range: beyond it nothing was computed), is at least MARGIN_FRACTION
!!   (5 %) of l, the one with the smallest predicted u(I1)/I1 (the first in the table on a
!!   tie).  When none qualifies the analysis fails with ERR_MODEL (exit 4) and a message that
!!   says why and suggests the range to try next; nothing is written.
!!
!! The work is three sweeps of independent points (module sweep_engine): the Floquet points
!! (candidate x amplitude), the band edges (one bisection each) and the candidates'
!! precision; each point is computed from its index alone and the results are assembled in
!! index order, so any order of computing (threads, or the ranks of bin/bifilar_mpi) gives
!! the same file.  Each sweep is checkpointed (OUTDIR/NAME.design.partial,
!! NAME.design_edges.partial, NAME.design_precision.partial) and resumed with --resume;
!! the other ranks of an MPI run build the same tasks from the deck (design_task; the
!! edges' sweep also from its payload, the list of edges).
!!
!! Output: OUTDIR/NAME.design (keys, the candidate table, the stable and unstable bands).
!!
!! The analysis for the driver: design_analysis_t (module analysis_base); it needs an
!! undamped torsion (deck_runs's undamped_ready) and runs before the analyses without a
!! sweep of their own (runs_first).
module design
    use kinds, only: dp
    use status, only: status_t
    use deck, only: deck_t
    use rig, only: rig_t, accuracy_t
    use floquet, only: STABILITY_MARGIN
    use budget, only: input_u_t
    use output_io, only: out_files_t
    use sweep_engine, only: sweep_task_t, sweep_options_t, sweep_report_t
    use analysis_base, only: analysis_t, WORD_LEN
    implicit none
    private

    !> The design's three sweeps (their analysis names: checkpoints NAME.STAGE.partial).
    character(len=*), parameter, public :: DESIGN_STAGES(3) = [character(len=16) :: &
        'design', 'design_edges', 'design_precision']

    !> A Floquet point is stable when its largest multiplier is <= 1 + DESIGN_TOLERANCE.
    real(dp), parameter, public :: DESIGN_TOLERANCE = STABILITY_MARGIN

    !> The recommended candidate lies at least this fraction of its l from the nearest l not
    !! known to be stable.
    real(dp), parameter, public :: MARGIN_FRACTION = 0.05_dp

    !> Band edges are bisected down to a bracket of EDGE_RTOL l.
    real(dp), parameter, public :: EDGE_RTOL = 1.0e-6_dp

    !> An interval of l at one b: unstable at amplitude index ia (ia = 0: a stable band, at
    !! every amplitude).
    type, public :: design_band_t
        integer :: ib = 0                       !! index of b in design_result_t%bs
        integer :: ia = 0                       !! amplitude index, 0 for a stable band
        real(dp) :: l_from = 0.0_dp, l_to = 0.0_dp  !! deck units
    end type design_band_t

    !> Everything the design computed.  Arrays over the candidates are (nl, nb) with nb the
    !! number of spacing pairs (b, b'); the per-point moduli (n_amplitudes, nl, nb).  Sentinels as in a chart: CHART_INVALID
    !! (-1) where pure torsion is not possible (the cables cannot reach), CHART_FAILED (-2)
    !! where the analysis failed; -1 in the precision columns where the period could not be
    !! computed.
    type, public :: design_result_t
        real(dp), allocatable :: ls(:), amps(:)         !! l (deck units), amplitudes (deg)
        real(dp), allocatable :: bs(:), bps(:)          !! each spacing pair's b and b'
        real(dp), allocatable :: modulus(:, :, :)       !! largest |multiplier| per point
        logical, allocatable :: stable(:, :)            !! at every amplitude
        real(dp), allocatable :: max_modulus(:, :)      !! over the amplitudes (or sentinel)
        real(dp), allocatable :: period_s(:, :)         !! period at amplitude_measure (s)
        real(dp), allocatable :: u_rel(:, :)            !! predicted u(I1)/I1
        real(dp), allocatable :: linear_error(:, :)     !! I1(linear formula)/I1 - 1
        real(dp), allocatable :: margin(:, :)           !! stable_margin_l (0 if unstable)
        real(dp), allocatable :: edge_l(:, :, :)        !! refined edge between l_i, l_i+1
        type(design_band_t), allocatable :: unstable(:) !! per amplitude, by b then amplitude
        type(design_band_t), allocatable :: stable_bands(:)  !! by b, increasing l
        integer :: n_grid_points = 0            !! Floquet points of the grid
        integer :: n_edges = 0                  !! edges refined
        integer :: n_bisection_points = 0       !! Floquet points of the bisections
        integer :: n_failed = 0                 !! grid points whose analysis failed (-2)
        integer :: n_stable = 0                 !! candidates stable at every amplitude
        integer :: n_qualified = 0              !! ... with the margin
        logical :: found = .false.              !! a candidate qualifies
        integer :: il = 0, ib = 0               !! the recommendation's indices
        real(dp) :: wall_seconds = 0.0_dp       !! the three sweeps
    end type design_result_t

    !> What a candidate is made from: the deck's rig (its body, I1 = inertia(1)), the
    !! accuracy of its runs, and the Floquet analysis's rtol and segments.
    type, public :: design_rig_t
        type(rig_t) :: rg
        type(accuracy_t) :: acc
        real(dp) :: fq_rtol = 1.0e-10_dp
        integer :: fq_segments = 1
    end type design_rig_t

    !> Analysis `design` (module analysis_base): OUTDIR/NAME.design from the three sweeps
    !! DESIGN_STAGES (checkpoints OUTDIR/NAME.STAGE.partial), run before the others; its part
    !! of the summary line: the candidates, the stable ones, the recommendation, the time.
    type, extends(analysis_t), public :: design_analysis_t
        type(design_result_t) :: res            !! what the design computed
        type(sweep_report_t) :: rep             !! how its sweeps went
    contains
        procedure, nopass :: word => design_word
        procedure, nopass :: owned_extensions => design_owned
        procedure, nopass :: sweeps => design_sweeps
        procedure, nopass :: runs_first => design_first
        procedure :: ready => design_analysis_ready
        procedure :: run => design_analysis_run
        procedure :: summary => design_summary
        procedure :: sweep_task => design_sweep_task
    end type design_analysis_t

    public :: run_design, design_ready, design_grid, design_sweep, candidate_modulus
    public :: candidate_precision, candidate_rig, design_task, design_rig_of

    interface
        !> The analysis `design` of a deck: the sweeps (design_sweep, checkpointed in
        !! outdir), then OUTDIR/NAME.design, or, when no candidate qualifies, ERR_MODEL with
        !! the reason and the range to try next (nothing written).  With `files` the file
        !! joins the run's others; without it it is committed at once.
        module subroutine run_design(d, outdir, res, stat, files, options, report)
            type(deck_t), intent(in) :: d           !! the deck
            character(len=*), intent(in) :: outdir  !! output directory
            type(design_result_t), intent(out) :: res
            type(status_t), intent(out) :: stat     !! ERR_DECK, ERR_MODEL (no candidate), ERR_IO
            type(out_files_t), intent(inout), optional, target :: files  !! the run's files
            type(sweep_options_t), intent(in), optional :: options  !! --resume, the interval
            type(sweep_report_t), intent(out), optional :: report   !! of the sweeps
        end subroutine run_design

        !> The preconditions of analyses = 'design', before any computing: pure torsion is an
        !! exact motion of the deck's body on equal cables, with b1 the vertical principal axis
        !! (its I1 is the one measured), and u_period lies below the shortest period of the
        !! candidates (ERR_DECK otherwise).
        module subroutine design_ready(d, stat)
            type(deck_t), intent(in) :: d           !! the deck
            type(status_t), intent(out) :: stat     !! ERR_DECK
        end subroutine design_ready

        !> The candidate grid of &design: l from l_min to l_max (nl values), the spacing pairs
        !! (bs(m), bps(m)): nb values of b (the deck's b when b_min = b_max = 0) times
        !! nb_prime values of b' (likewise), b fastest; amplitudes j amplitude_max /
        !! n_amplitudes.
        module subroutine design_grid(d, ls, bs, bps, amps)
            type(deck_t), intent(in) :: d           !! the deck
            real(dp), allocatable, intent(out) :: ls(:), bs(:), bps(:), amps(:)
        end subroutine design_grid

        !> The whole design of deck d (without writing): the three sweeps, the bands, the
        !! margins and the recommendation (res%found).  `label` names the progress lines.  With
        !! `outdir` the sweeps are checkpointed there (options: --resume, the interval); stat
        !! and report say how the sweeps went (a failure: a rank that cannot take part, a
        !! checkpoint that cannot be written).
        module subroutine design_sweep(d, res, label, stat, outdir, options, report)
            type(deck_t), intent(in) :: d           !! the deck (checked by design_ready)
            type(design_result_t), intent(out) :: res
            character(len=*), intent(in) :: label   !! progress label ('' for none)
            type(status_t), intent(out), optional :: stat
            character(len=*), intent(in), optional :: outdir    !! checkpoints' folder
            type(sweep_options_t), intent(in), optional :: options
            type(sweep_report_t), intent(out), optional :: report   !! of the three sweeps
        end subroutine design_sweep

        !> The largest Floquet multiplier of pure torsion of candidate (l, b, b') at amp_deg,
        !! with the deck's &floquet rtol and segments (CHART_INVALID, CHART_FAILED as in a
        !! chart).
        module subroutine candidate_modulus(dr, l, b, bp, amp_deg, modulus)
            type(design_rig_t), intent(in) :: dr    !! the deck's rig and Floquet settings
            real(dp), intent(in) :: l, b, bp        !! candidate (deck units)
            real(dp), intent(in) :: amp_deg         !! torsion amplitude (degrees)
            real(dp), intent(out) :: modulus        !! largest |multiplier| or sentinel
        end subroutine candidate_modulus

        !> The precision of candidate (l, b, b') measured by one period at amp_deg: its exact
        !! period (s), I1 inverted back from it (invert_periods) and the first-order budget of
        !! that inversion (period_budget): u(I1)/I1; and the linear formula's relative error
        !! there.
        module subroutine candidate_precision(dr, l, b, bp, amp_deg, u, period_s, u_rel, &
                                              linear_error, stat)
            type(design_rig_t), intent(in) :: dr    !! the deck's rig (the body, I1 = inertia(1))
            real(dp), intent(in) :: l, b, bp        !! candidate (deck units)
            real(dp), intent(in) :: amp_deg         !! amplitude of the measurement (degrees)
            type(input_u_t), intent(in) :: u        !! standard uncertainties
            real(dp), intent(out) :: period_s       !! exact period (s)
            real(dp), intent(out) :: u_rel          !! predicted u(I1)/I1
            real(dp), intent(out) :: linear_error   !! m g b b' T^2/(16 pi^2 l) / I1 - 1
            type(status_t), intent(out) :: stat     !! ERR_DECK (cables cannot reach), ERR_NUMERIC
        end subroutine candidate_precision

        !> The rig with the candidate's cables l = l', support spacing b and body spacing b'
        !! (deck units; b' moves the body's attachment points symmetrically).
        module pure function candidate_rig(rg, l, b, bp) result(rr)
            type(rig_t), intent(in) :: rg           !! the deck's rig
            real(dp), intent(in) :: l, b, bp        !! candidate (deck units)
            type(rig_t) :: rr
        end function candidate_rig

        !> The task of one of the design's sweeps, by its name (DESIGN_STAGES), as the other
        !! ranks of an MPI run build it: from the deck, and for the edges from the sweep's
        !! payload (edges_payload); ERR_DECK for another name.
        module subroutine design_task(stage, d, payload, task, stat)
            character(len=*), intent(in) :: stage   !! 'design', 'design_edges', 'design_precision'
            type(deck_t), intent(in) :: d           !! the deck
            real(dp), intent(in) :: payload(:)      !! the edges' sweep: il, ib, ia, left_stable
            class(sweep_task_t), allocatable, intent(out) :: task
            type(status_t), intent(out) :: stat     !! ERR_DECK: no such stage
        end subroutine design_task

        !> What the candidates of deck d are made from.
        module pure function design_rig_of(d) result(dr)
            type(deck_t), intent(in) :: d           !! the deck
            type(design_rig_t) :: dr
        end function design_rig_of

        !> The preconditions of design: design_ready, and no &damping (undamped_ready).
        module subroutine design_analysis_ready(self, d, stat)
            class(design_analysis_t), intent(inout) :: self
            type(deck_t), intent(in) :: d           !! the deck
            type(status_t), intent(out) :: stat     !! ERR_DECK
        end subroutine design_analysis_ready

        !> The run (run_design into the run's files; its sweeps' warning kept).
        module subroutine design_analysis_run(self, d, outdir, files, stat, options)
            class(design_analysis_t), intent(inout) :: self
            type(deck_t), intent(in) :: d           !! the deck
            character(len=*), intent(in) :: outdir  !! output directory
            type(out_files_t), intent(inout) :: files   !! the run's files
            type(status_t), intent(out) :: stat     !! ERR_DECK, ERR_MODEL (no candidate), ERR_IO
            type(sweep_options_t), intent(in), optional :: options  !! --resume, the interval
        end subroutine design_analysis_run

        !> ' design N candidates x N amplitudes, N stable, recommended l = ..., b = ...,
        !! b_prime = ..., u(I1)/I1 = ..., T s[ on N ranks][, N failed points][resume];'
        module function design_summary(self, d) result(s)
            class(design_analysis_t), intent(in) :: self
            type(deck_t), intent(in) :: d           !! the deck
            character(len=:), allocatable :: s
        end function design_summary

        !> The task of one of its sweeps on the other ranks of an MPI run (design_task).
        module subroutine design_sweep_task(self, sweep, d, payload, task, stat)
            class(design_analysis_t), intent(in) :: self
            character(len=*), intent(in) :: sweep   !! one of DESIGN_STAGES
            type(deck_t), intent(in) :: d           !! the deck
            real(dp), intent(in) :: payload(:)      !! the sweep's payload (the edges')
            class(sweep_task_t), allocatable, intent(out) :: task
            type(status_t), intent(out) :: stat     !! ERR_DECK: no such stage
        end subroutine design_sweep_task
    end interface

contains

    !> The word of &scene analyses.
    function design_word() result(w)
        character(len=:), allocatable :: w
        w = 'design'
    end function design_word

    !> The file it writes: NAME.design.
    subroutine design_owned(names)
        character(len=WORD_LEN), allocatable, intent(out) :: names(:)
        names = [character(len=WORD_LEN) :: '.design']
    end subroutine design_owned

    !> Its sweeps: DESIGN_STAGES.
    subroutine design_sweeps(names)
        character(len=WORD_LEN), allocatable, intent(out) :: names(:)
        names = [character(len=WORD_LEN) :: DESIGN_STAGES]
    end subroutine design_sweeps

    !> The design runs before the analyses without it (no file of the deck staged meanwhile,
    !! but a chart's).
    logical function design_first()
        design_first = .true.
    end function design_first

end module design
