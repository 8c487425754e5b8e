!> The input deck: a namelist file with the groups &scene, &suspension, &body, &start,
!! &integration, &cables, &floquet, &chart, &output, &design, &damping, &measurement and
!! &tensor (see input/*.nml and doc/deck.md), composed of one type per group (deck_t%scene,
!! deck_t%suspension, ...: each defined in the layer that uses it, see module deck_base).
!!
!! read_deck reads the file once into memory (deck_t%text, which also travels to the other
!! ranks of an MPI run: read_deck_text), then in three named steps:
!! - read: each group from its own text (the group's read_text), a read error explained by
!!   module namelist_text;
!! - check (check_deck): each group's check in the order of the groups, each against the
!!   groups before it as the run takes them, then the checks across groups (a measuring
!!   deck gives every physical input itself; a platform with the analyses that model it).
!!   No check changes a value;
!! - normalise (normalise_deck): the values the run takes where they differ from those
!!   given (a platform's b = 2 radius, the mass centre from cg_depth, the cycles of every
!!   period, words in lower case, angles modulo 2 pi, files relative to the deck's folder).
!! Every problem is an ERR_DECK status whose message names the deck, the group, the variable
!! and its value, what is wrong and what is allowed.  Cable reachability is checked by the
!! rig layer (module rig).
!!
!! Only analyses/ and app/ use this module (tests/module_graph.sh --check): the layers below
!! take the group types they need.
module deck
    use, intrinsic :: iso_fortran_env, only: int64
    use kinds, only: dp
    use status, only: status_t, set_error, STATUS_OK, ERR_DECK
    use text, only: itoa, next_word, rshort, quoted
    use lines, only: read_line, LINE_MAX
    use fptraps, only: traps_off, traps_restore, NTRAPS
    use deck_base, only: deck_source_t, deck_group_t
    use namelist_text, only: text_line_t, check_group_names, scan_group, long_text, &
        subscript_problem, explain, with_allowed
    use value_checks, only: bad
    use rig_groups, only: suspension_group_t, body_group_t, start_group_t, &
        integration_group_t, cables_group_t, damping_group_t, TAU_END_MAX
    use measure_groups, only: measurement_group_t, tensor_group_t
    use calibration_group, only: calibration_group_t
    use analysis_groups, only: scene_group_t, output_group_t, floquet_group_t, &
        chart_group_t, design_group_t, OUTPUT_COLUMNS
    implicit none
    private

    !> The deck: its source (path, name, text) and its groups.
    type, extends(deck_source_t), public :: deck_t
        type(scene_group_t) :: scene
        type(suspension_group_t) :: suspension
        type(body_group_t) :: body
        type(start_group_t) :: start
        type(integration_group_t) :: integration
        type(cables_group_t) :: cables
        type(floquet_group_t) :: floquet
        type(chart_group_t) :: chart
        type(output_group_t) :: output
        type(design_group_t) :: design
        type(damping_group_t) :: damping
        type(measurement_group_t) :: measurement
        type(tensor_group_t) :: tensor
        type(calibration_group_t) :: calibration
    end type deck_t

    public :: read_deck, read_deck_text, analysis_requested, deck_echo
    public :: OUTPUT_COLUMNS, TAU_END_MAX

    !> Namelist groups a deck may contain, in the order they are read and checked.
    character(len=*), parameter :: GROUPS_ALLOWED = 'scene suspension body start '// &
        'integration cables floquet chart output design damping measurement tensor '// &
        'calibration'
    integer, parameter :: MAX_LINE = LINE_MAX           !! longest deck line (characters)
    integer, parameter :: MAX_DECK_BYTES = 1000000      !! largest deck (bytes)

contains

    !> Read and validate the deck at `path` into d: the file is read once (its size, every
    !! line's length), then parsed (read_deck_text's work).  Absent optional groups keep
    !! defaults; &suspension and &body are required.
    subroutine read_deck(path, d, stat)
        character(len=*), intent(in) :: path        !! deck file
        type(deck_t), intent(out) :: d              !! the effective deck (defaults + file)
        type(status_t), intent(out) :: stat         !! ERR_DECK with a message on any problem
        type(text_line_t), allocatable :: ls(:)
        call load_lines(path, ls, stat)
        if (stat%code /= STATUS_OK) return
        call parse_deck(path, ls, d, stat)
    end subroutine read_deck

    !> As read_deck, from the deck's text already in memory (deck_t%text of the same deck
    !! read elsewhere, e.g. on rank 0 of an MPI run): the same checks, the same deck.
    subroutine read_deck_text(path, text, d, stat)
        character(len=*), intent(in) :: path        !! the deck as given (names, messages)
        character(len=*), intent(in) :: text        !! its lines joined by newlines
        type(deck_t), intent(out) :: d
        type(status_t), intent(out) :: stat
        type(text_line_t), allocatable :: ls(:)
        integer :: n, i, i0
        stat%code = STATUS_OK
        n = count([(text(i:i) == achar(10), i = 1, len(text))]) + 1
        allocate (ls(n))
        i0 = 1
        n = 0
        do i = 1, len(text) + 1
            if (i <= len(text)) then
                if (text(i:i) /= achar(10)) cycle
            end if
            n = n + 1
            ls(n)%s = text(i0:i - 1)
            i0 = i + 1
        end do
        if (len(text) == 0) n = 0
        call parse_deck(path, ls(1:n), d, stat)
    end subroutine read_deck_text

    !> The deck file's lines, read once: a file larger than MAX_DECK_BYTES, a line longer than
    !! MAX_LINE characters or a file that cannot be read is refused.
    subroutine load_lines(path, ls, stat)
        character(len=*), intent(in) :: path        !! deck file
        type(text_line_t), allocatable, intent(out) :: ls(:)
        type(status_t), intent(inout) :: stat       !! ERR_DECK
        type(text_line_t), allocatable :: grown(:)
        character(len=:), allocatable :: line
        character(len=512) :: msg
        integer :: u, ios, n
        integer(int64) :: fsize, nbytes
        msg = ''
        inquire (file=path, size=fsize, iostat=ios)
        if (ios == 0 .and. fsize > MAX_DECK_BYTES) then
            call set_error(stat, ERR_DECK, 'the deck is larger than '//itoa(MAX_DECK_BYTES)// &
                           ' bytes; allowed: decks of at most '//itoa(MAX_DECK_BYTES)//' bytes')
            return
        end if
        open (newunit=u, file=path, status='old', action='read', form='formatted', &
              access='sequential', iostat=ios, iomsg=msg)
        if (ios /= 0) then
            call set_error(stat, ERR_DECK, 'cannot open the deck: '//trim(msg)//'; allowed: '// &
                           'a readable text file of namelist groups')
            return
        end if
        allocate (ls(64))
        n = 0
        nbytes = 0
        do
            call read_line(u, line, ios, msg)
            if (ios > 0) then
                call set_error(stat, ERR_DECK, 'cannot read the deck: '//trim(msg)// &
                               '; allowed: a readable text file of namelist groups')
                exit
            end if
            if (ios < 0) exit
            n = n + 1
            nbytes = nbytes + len(line) + 1
            if (len(line) > MAX_LINE) then
                call set_error(stat, ERR_DECK, 'line '//itoa(n)//' is longer than '// &
                               itoa(MAX_LINE)//' characters; allowed: lines of at most '// &
                               itoa(MAX_LINE)//' characters (a title holds 256)')
                exit
            end if
            if (nbytes > MAX_DECK_BYTES) then
                call set_error(stat, ERR_DECK, 'the deck is larger than '// &
                               itoa(MAX_DECK_BYTES)//' bytes; allowed: decks of at most '// &
                               itoa(MAX_DECK_BYTES)//' bytes')
                exit
            end if
            if (n > size(ls)) then
                allocate (grown(2*size(ls)))
                grown(1:n - 1) = ls(1:n - 1)
                call move_alloc(grown, ls)
            end if
            call move_alloc(line, ls(n)%s)
        end do
        close (u, iostat=ios)
        if (stat%code /= STATUS_OK) return
        ls = ls(1:n)
    end subroutine load_lines

    !> Parse a deck's lines into d: the group names, each group read (read_group), the
    !! checks (check_deck), the normalisation (normalise_deck).
    subroutine parse_deck(path, ls, d, stat)
        character(len=*), intent(in) :: path        !! the deck as given
        type(text_line_t), intent(in) :: ls(:)      !! its lines
        type(deck_t), intent(out) :: d
        type(status_t), intent(inout) :: stat
        character(len=:), allocatable :: seen
        logical :: halting(NTRAPS)
        integer :: k

        stat%code = STATUS_OK
        d%path = path
        d%name = deck_name(path)
        d%text = ''
        do k = 1, size(ls)
            if (k > 1) d%text = d%text//achar(10)
            d%text = d%text//ls(k)%s
        end do
        call check_group_names(ls, GROUPS_ALLOWED, stat, seen)
        if (stat%code /= STATUS_OK) return
        if (size(ls) == 0) then
            call set_error(stat, ERR_DECK, 'the deck is empty or not a regular file; '// &
                           'allowed: a namelist file with &suspension and &body')
            return
        end if
        ! Values such as 1e400 overflow inside the run-time library: read without traps, the
        ! finiteness checks catch the result.
        call traps_off(halting)
        call read_group(d%scene, .false.)
        call read_group(d%suspension, .true.)
        call read_group(d%body, .true.)
        call read_group(d%start, .false.)
        call read_group(d%integration, .false.)
        call read_group(d%cables, .false.)
        call read_group(d%floquet, .false.)
        call read_group(d%chart, .false.)
        call read_group(d%output, .false.)
        call read_group(d%design, .false.)
        call read_group(d%damping, .false.)
        call read_group(d%measurement, .false.)
        call read_group(d%tensor, .false.)
        call read_group(d%calibration, .false.)
        call traps_restore(halting)
        if (stat%code /= STATUS_OK) return
        call check_deck(d, stat)
        if (stat%code /= STATUS_OK) return
        call normalise_deck(d)

    contains

        !> Read one group (when present) with its read_text, and explain any failure.
        subroutine read_group(g, required)
            class(deck_group_t), intent(inout) :: g     !! the group: defaults in, values out
            logical, intent(in) :: required             !! absence is an error
            logical :: found, complete
            character(len=:), allocatable :: grp, spec, items, rec, why
            integer, allocatable :: breaks(:)
            integer :: ios
            character(len=512) :: msg

            if (stat%code /= STATUS_OK) return
            grp = g%name()
            spec = g%spec()
            if (index(seen, ' '//grp//' ') == 0) then   ! no line starts the group
                if (required) call set_error(stat, ERR_DECK, '&'//grp// &
                    ' group missing; allowed: a deck with &suspension and &body (both required)')
                return
            end if
            call scan_group(ls, grp, found, complete, items, breaks, rec)
            if (.not. found) then
                if (required) call set_error(stat, ERR_DECK, '&'//grp// &
                    ' group missing; allowed: a deck with &suspension and &body (both required)')
                return
            end if
            ! what the run-time library cannot be trusted with never reaches it
            why = subscript_problem(items, breaks)
            if (len(why) == 0) why = long_text(items)
            if (len(why) > 0) then
                call set_error(stat, ERR_DECK, with_allowed('cannot read namelist group &'// &
                               grp//': '//why, '', spec))
                return
            end if
            if (.not. complete) then
                call set_error(stat, ERR_DECK, 'cannot read namelist group &'//grp// &
                    ': no closing ''/'' before the end of the file (truncated deck?); '// &
                    'allowed: each group closed by ''/'' (or &end)')
                return
            end if
            msg = ''
            call g%read_text(rec, ios, msg)
            if (ios == 0) return
            why = explain(items, grp, spec)
            if (len(why) > 0) then
                call set_error(stat, ERR_DECK, with_allowed('cannot read namelist group &'// &
                               grp//': '//why, ' (reader: '//trim(msg)//')', spec))
            else
                call set_error(stat, ERR_DECK, with_allowed('cannot read namelist group &'// &
                               grp//': '//trim(msg), '', spec))
            end if
        end subroutine read_group

    end subroutine parse_deck

    !> Check every group, in the order of the groups (the first problem is reported), each
    !! against the groups before it as the run takes them (normalised copies: the body
    !! against the suspension's b_prime, a platform's 2 radius_prime), then across groups.
    !! No value of d changes.
    subroutine check_deck(d, stat)
        type(deck_t), intent(in) :: d               !! the deck as read
        type(status_t), intent(inout) :: stat       !! ERR_DECK on the first problem
        type(scene_group_t) :: scene
        type(suspension_group_t) :: sus
        type(start_group_t) :: sta
        call d%scene%check(stat)
        scene = d%scene
        if (stat%code == STATUS_OK) call scene%normalise()
        call d%suspension%check(stat)
        sus = d%suspension
        if (stat%code == STATUS_OK) call sus%normalise()
        call d%body%check(sus, stat)
        call d%start%check(stat)
        sta = d%start
        if (stat%code == STATUS_OK) call sta%normalise()
        call d%integration%check(stat)
        call d%cables%check(stat)
        call d%floquet%check(stat)
        ! (a platform given point by point has no l or radius to chart: the default axes
        ! are refused only when a chart is asked for)
        if (scene%requested('chart') .or. .not. (sus%cables > 2 .and. sus%pointwise())) &
            call d%chart%check(sus, stat)
        call d%output%check(sus, stat)
        if (scene%requested('design')) call d%design%check(sus, d%body, stat)
        call d%damping%check(sus, d%body, stat)
        call d%measurement%check(sus, d%body, sta, stat)
        call d%tensor%check(sus, d%body, scene%requested('tensor'), stat)
        if (scene%requested('tensor') .and. stat%code == STATUS_OK .and. &
            (len_trim(d%measurement%tare) > 0 .or. len_trim(d%measurement%calibration) > 0)) &
            call set_error(stat, ERR_DECK, '&measurement tare = '// &
                quoted(trim(d%measurement%tare))//', calibration = '// &
                quoted(trim(d%measurement%calibration))//' with analyses = ''tensor'': a '// &
                'tare''s or a calibration''s output serves identify''s one axis, and the '// &
                'tensor''s fit takes neither; allowed: both '''' in a deck with tensor (run '// &
                'identify from a deck of its own)')
        call check_platform_deck(scene, sus, d%body, sta, d%tensor, stat)
        if (scene%requested('calibrate')) call d%calibration%check(stat)
        call check_measuring(scene, sus, d%body, stat)
    end subroutine check_deck

    !> A platform (cables >= 3) with the analyses that model it: simulate, floquet, chart,
    !! design, identify and (three cables) tensor, not work_precision; it starts turned about the vertical
    !! (&start mode = 'raised', no tilt).  floquet, chart and design analyse the torsion of
    !! inextensible cables: n = 3, model = 'kane'; design and identify the regular polygon
    !! (radius, radius_prime, l); design with the mass centre on its axis.  identify with
    !! the mass centre on the axis takes the pure torsion of the equivalent pair b = 2 radius;
    !! off it the platform's model (three cables) or its elastic cables' (four or more):
    !! module platform_measure.
    subroutine check_platform_deck(scene, sus, bod, sta, ten, stat)
        type(scene_group_t), intent(in) :: scene        !! normalised
        type(suspension_group_t), intent(in) :: sus     !! normalised
        type(body_group_t), intent(in) :: bod
        type(start_group_t), intent(in) :: sta          !! normalised
        type(tensor_group_t), intent(in) :: ten         !! normalised
        type(status_t), intent(inout) :: stat
        character(len=:), allocatable :: which
        character(len=*), parameter :: TORSION = 'floquet chart design'
        integer :: k
        if (stat%code /= STATUS_OK .or. sus%cables <= 2) return
        if (scene%requested('tensor')) then
            call check_platform_tensor(scene, sus, ten, stat)
            if (stat%code /= STATUS_OK) return
        end if
        which = ''
        if (scene%requested('work_precision')) which = 'work_precision'
        if (len(which) > 0) then
            call bad(stat, 'scene', 'analyses', ''''//trim(scene%analyses)//'''', &
                     which//' models two cables, not a platform of '//itoa(sus%cables)// &
                     ' cables', 'simulate, floquet, chart, design and identify with '// &
                     'cables >= 3')
            return
        end if
        if (trim(sta%mode) /= 'raised') then
            call bad(stat, 'start', 'mode', ''''//trim(sta%mode)//'''', 'the paper''s '// &
                     'angles of a bifilar on a platform of '//itoa(sus%cables)//' cables', &
                     'mode = ''raised'': the platform released at rest turned by amplitude '// &
                     '(degrees) about the vertical through its mass centre')
            return
        end if
        if (sta%tilt /= 0.0_dp) then
            call bad(stat, 'start', 'tilt', rshort(sta%tilt), 'the paper''s tilt of a '// &
                     'bifilar on a platform of '//itoa(sus%cables)//' cables', 'tilt = 0: '// &
                     'the platform released at rest turned by amplitude about the vertical')
            return
        end if
        do k = 1, 3
            which = trim(word_of(TORSION, k))
            if (.not. scene%requested(which)) cycle
            if (sus%cables >= 4 .or. trim(scene%model) == 'elastic') then
                call bad(stat, 'scene', 'analyses', ''''//trim(scene%analyses)//'''', &
                         which//' analyses the periodic torsion of inextensible cables; '// &
                         'a platform of '//itoa(sus%cables)//' cables with model = '''// &
                         trim(scene%model)//''' has elastic cables'//trim(merge( &
                         ' (n >= 4: statically indeterminate when inextensible)', &
                         '                                                     ', &
                         sus%cables >= 4)), 'floquet, chart and design with cables = 3 '// &
                         'and model = ''kane''; simulate for any platform')
                return
            end if
        end do
        which = ''
        if (scene%requested('identify')) which = 'identify'
        if (scene%requested('design')) which = 'design'
        if (len(which) == 0) return
        if (sus%pointwise()) then
            call bad(stat, 'suspension', 'support_points', 'given', which//' on a platform '// &
                     'given point by point', 'the regular polygon (radius, radius_prime, l) '// &
                     'with analyses = '''//which//'''')
        else if ((bod%cg_offset /= 0.0_dp .or. bod%cg_offset_y /= 0.0_dp) .and. &
                 which == 'design') then
            call bad(stat, 'body', 'cg_offset', rshort(bod%cg_offset)//', '// &
                     rshort(bod%cg_offset_y), which//' on a platform of '//itoa(sus%cables)// &
                     ' cables with the mass centre off its axis', 'cg_offset = 0, 0 with '// &
                     'analyses = '''//which//''' (the pure torsion of the centred body)')
        end if
    contains
        !> The k-th blank-separated word of s.
        function word_of(s, k) result(w)
            character(len=*), intent(in) :: s
            integer, intent(in) :: k
            character(len=:), allocatable :: w
            integer :: i1, i2, j
            i2 = 0
            w = ''
            do j = 1, k
                call next_word(s, i2, i1)
                if (i1 == 0) return
            end do
            w = s(i1:i2)
        end function word_of
    end subroutine check_platform_deck

    !> analyses = 'tensor' on a platform: three cables (the regular polygon: radius,
    !! radius_prime, l; or point by point), the paper's inextensible model, the six
    !! entries alone, and the platform's own mass and inertia a fixture that stays with
    !! the hang.
    subroutine check_platform_tensor(scene, sus, ten, stat)
        type(scene_group_t), intent(in) :: scene        !! normalised
        type(suspension_group_t), intent(in) :: sus     !! normalised, cables >= 3
        type(tensor_group_t), intent(in) :: ten         !! normalised
        type(status_t), intent(inout) :: stat
        if (sus%cables /= 3) then
            call bad(stat, 'suspension', 'cables', itoa(sus%cables), 'tensor on a '// &
                     'platform of '//itoa(sus%cables)//' cables (statically indeterminate '// &
                     'with inextensible cables: no model of its torsion with the body '// &
                     'anywhere on it)', 'cables = 3 (or 2: the bifilar) with analyses = '// &
                     '''tensor''')
        else if (trim(scene%model) /= 'kane') then
            call bad(stat, 'scene', 'model', ''''//trim(scene%model)//'''', 'tensor on a '// &
                     'platform fits the inextensible cables'' model', 'model = ''kane''')
        else if (ten%estimates_cg()) then
            call bad(stat, 'tensor', 'estimate', ''''//trim(ten%estimate)//'''', 'the mass '// &
                     'centre fitted on a platform (its attitude is the platform''s, not the '// &
                     'line CD''s)', 'estimate = ''tensor'' on a platform, the mass centre '// &
                     'given by cg_depth, cg_offset, cg_offset_y')
        else if (ten%fixture_mass > 0.0_dp .and. trim(ten%fixture_frame) /= 'hang') then
            call bad(stat, 'tensor', 'fixture_frame', ''''//trim(ten%fixture_frame)//'''', &
                     'a fixture that turns with the body on a platform (the platform, the '// &
                     'fixture of every platform hang, does not turn with the body)', &
                     'fixture_frame = ''hang'': fixture_cg from the centre of the '// &
                     'platform''s attachment points along its x, y and up, fixture_inertia '// &
                     'in those axes')
        end if
    end subroutine check_platform_tensor

    !> A deck that measures (identify, tensor, design) gives every physical input itself
    !! (the defaults are the paper's dimensionless scene).
    subroutine check_measuring(scene, sus, bod, stat)
        type(scene_group_t), intent(in) :: scene        !! normalised
        type(suspension_group_t), intent(in) :: sus     !! normalised
        type(body_group_t), intent(in) :: bod
        type(status_t), intent(inout) :: stat
        character(len=:), allocatable :: what, missing
        if (stat%code /= STATUS_OK) return
        what = ''
        if (scene%requested('identify')) what = 'identify'
        if (scene%requested('calibrate')) what = 'calibrate'
        if (scene%requested('tensor')) what = 'tensor'
        if (scene%requested('design')) what = 'design'
        if (len(what) == 0) return
        missing = ''
        call need('&suspension g', sus%gave('g'))
        call need('&body mass', bod%gave('mass'))
        if (sus%cables == 2 .or. .not. sus%pointwise()) call need('&suspension l', sus%gave('l'))
        if (sus%cables == 2) then
            call need('&suspension l_prime', sus%gave('l_prime'))
            call need('&suspension b', sus%gave('b'))
            call need('&suspension b_prime', sus%gave('b_prime'))
            ! (a tensor deck's mass centre may come from its table of hangs: checked there)
            if (what /= 'tensor') &
                call need('&body the mass centre (cg_depth and cg_offset, or r and lambda)', &
                          bod%gave('cg_depth') .or. (bod%gave('r') .and. bod%gave('lambda')))
        else if (sus%pointwise()) then
            call need('&suspension support_points', sus%gave('support_points'))
            call need('&suspension body_points', sus%gave('body_points'))
            call need('&suspension lengths', sus%gave('lengths'))
        else
            call need('&suspension radius', sus%gave('radius'))
            call need('&suspension radius_prime', sus%gave('radius_prime'))
        end if
        if (len(missing) > 0) call set_error(stat, ERR_DECK, 'not given: '//missing// &
            '; a deck with analyses = '''//what//''' gives every physical input itself (the '// &
            'defaults are the paper''s dimensionless scene); allowed: g, mass, l, l_prime, '// &
            'b and b_prime (the full distances between the two cables on the support and on '// &
            'the body) in one system of units, and the mass centre')
    contains
        subroutine need(name, given)
            character(len=*), intent(in) :: name
            logical, intent(in) :: given
            if (given) return
            if (len(missing) > 0) missing = missing//', '
            missing = missing//name
        end subroutine need
    end subroutine check_measuring

    !> The values the run takes where they differ from those given (each group's normalise,
    !! in the order of the groups; the body's after the suspension's, whose b_prime places
    !! the mass centre; &design's only when the analysis is asked for).
    subroutine normalise_deck(d)
        type(deck_t), intent(inout) :: d            !! the deck, checked
        call d%scene%normalise()
        call d%suspension%normalise()
        call d%body%normalise(d%suspension)
        call d%start%normalise()
        call d%integration%normalise()
        call d%chart%normalise()
        call d%output%normalise(d%suspension%cables)
        if (d%scene%requested('design')) call d%design%normalise()
        call d%measurement%normalise(d%path)
        call d%tensor%normalise(d%path)
    end subroutine normalise_deck

    !> True when `word` is one of the blank-separated words of &scene analyses.
    logical function analysis_requested(d, word)
        type(deck_t), intent(in) :: d               !! the deck
        character(len=*), intent(in) :: word        !! analysis name, e.g. 'simulate'
        analysis_requested = d%scene%requested(word)
    end function analysis_requested

    !> Write the effective deck as '# ' comment lines, one namelist-like line per group
    !! (each group's echo; &cables only with model = 'elastic', &floquet, &chart, &design,
    !! &measurement and &tensor only when that analysis is requested, &output when it
    !! differs from every column, &damping when there is some or identify is requested);
    !! the reals are the shortest decimals that read back exactly.
    subroutine deck_echo(d, unit, ios)
        type(deck_t), intent(in) :: d               !! the deck
        integer, intent(in) :: unit                 !! open formatted unit
        integer, intent(inout) :: ios               !! writer's iostat: nothing written when
                                                    !! /= 0 on entry; the first failure
        call put('# deck '//d%path)
        call put(d%scene%echo())
        call put(d%suspension%echo())
        call put(d%body%echo())
        call put(d%start%echo())
        call put(d%integration%echo())
        if (trim(d%scene%model) == 'elastic') call put(d%cables%echo())
        if (analysis_requested(d, 'floquet')) call put(d%floquet%echo())
        if (analysis_requested(d, 'chart')) call put(d%chart%echo())
        if (analysis_requested(d, 'design')) call put(d%design%echo())
        if (trim(d%output%columns) /= OUTPUT_COLUMNS) call put(d%output%echo())
        if (d%damping%c_v /= 0.0_dp .or. d%damping%c_q /= 0.0_dp .or. &
            analysis_requested(d, 'identify')) call put(d%damping%echo())
        if (analysis_requested(d, 'identify') .or. analysis_requested(d, 'calibrate')) &
            call put(d%measurement%echo())
        if (analysis_requested(d, 'calibrate')) call put(d%calibration%echo())
        if (analysis_requested(d, 'tensor')) call put(d%tensor%echo())

    contains

        subroutine put(text)
            character(len=*), intent(in) :: text
            if (ios == 0) write (unit, '(a)', iostat=ios) text
        end subroutine put

    end subroutine deck_echo

    !> File name without directory and without a trailing '.nml'.
    pure function deck_name(path) result(nm)
        character(len=*), intent(in) :: path        !! deck path
        character(len=:), allocatable :: nm
        integer :: i
        i = index(path, '/', back=.true.)
        nm = trim(path(i + 1:))
        if (len(nm) > 4) then
            if (nm(len(nm) - 3:) == '.nml') nm = nm(1:len(nm) - 4)
        end if
        if (len(nm) == 0) nm = 'deck'
    end function deck_name

end module deck
