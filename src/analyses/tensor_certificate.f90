!> The certificate of a `tensor` run: OUTDIR/NAME.certificate.html, one self-contained page
!! for A4 (module certificate) that an engineer can attach to a test report.  It holds the
!! title; the result: the tensor about the mass centre in the body frame with each entry's
!! standard u, the principal moments with U = k u, k and the coverage, the principal axes
!! with their u; the mass centre the hangs assumed; the body and the rig as measured, with
!! every input's u; the method and the model; the budget sorted by contribution; every
!! check with its value (positive definite, the triangle inequalities, the fit's chi^2 and
!! p, the projection solution's distance, the directions' condition and the smallest angle
!! between two hangs, each period's definition, the Monte Carlo); the warnings; the hangs
!! as timed with their u; a figure (each hang's measured vertical moment with its u against
!! the fitted tensor's); and, at its foot, the program's version, the deck's CRC-64 and the
!! date.  It is written for every tensor deck that fits a table of hangs.
submodule (tensor) tensor_certificate
    use kinds, only: deg
    use text, only: itoa, sci, fixed
    use stats, only: NU_INFINITE
    use crc64, only: crc64_of, hex16
    use version, only: BIFILAR_VERSION
    use svg_plot, only: svg_plot_t, svg_new, svg_add, svg_render
    use certificate, only: certificate_t, cert_new, cert_section, cert_text, cert_table, &
        cert_row, cert_figure, cert_write, cert_note, cert_now, CELL
    use tensor_checks, only: TRIANGLE_MARGIN, NEAR_PARALLEL_DEG
    use tensor_fit, only: tensor_fit_t, tensor_problem_t, DRIFT_MAX
    use status, only: set_error, ERR_NUMERIC
    implicit none

    !> The names of the six entries, in their order.
    character(len=4), parameter :: NAMES(6) = ['J_xx', 'J_yy', 'J_zz', 'J_xy', 'J_xz', 'J_yz']

contains

    !> Write OUTDIR/NAME.certificate.html for a tensor run into the run's files.
    module procedure write_tensor_certificate
        stat%code = 0
        select type (fit)
        type is (tensor_fit_t)
            select type (prob)
            type is (tensor_problem_t)
                call write_page(d, outdir, res, fit, prob, drift, limit, u_x_mc, &
                                u_moments_mc, files, stat)
                return
            end select
        end select
        call set_error(stat, ERR_NUMERIC, 'tensor: the certificate was given no fit')
    end procedure write_tensor_certificate

    !> The page of a fit and its problem.
    subroutine write_page(d, outdir, res, fit, prob, drift, limit, u_x_mc, u_moments_mc, &
                          files, stat)
        type(deck_t), intent(in) :: d
        character(len=*), intent(in) :: outdir
        type(tensor_result_t), intent(in) :: res
        type(tensor_fit_t), intent(in) :: fit
        type(tensor_problem_t), intent(in) :: prob
        real(dp), intent(in) :: drift(:), limit(:), u_x_mc(6), u_moments_mc(3)
        type(out_files_t), intent(inout) :: files
        type(status_t), intent(out) :: stat
        type(certificate_t) :: c
        character(len=:), allocatable :: crc
        integer :: j
        crc = '(none)'
        if (allocated(d%text)) crc = hex16(crc64_of(d%text))
        if (d%suspension%cables > 2) then
            c = cert_new('Inertia tensor of a body from hangs on a trifilar platform', &
                         trim(d%scene%title), BIFILAR_VERSION, d%path, crc)
        else
            c = cert_new('Inertia tensor of a body from bifilar hangs', trim(d%scene%title), &
                         BIFILAR_VERSION, d%path, crc)
        end if
        call result_part(c, res, fit, u_x_mc, u_moments_mc)
        call centre_part(c, d, prob)
        call rig_part(c, d, prob)
        call method_part(c, d, res, fit, prob)
        call budget_part(c, fit)
        call checks_part(c, res, fit, prob, drift, limit, u_moments_mc)
        if (len(res%warning) > 0) call cert_note(c, 'Warning: '//res%warning)
        do j = 1, size(res%warnings)
            call cert_note(c, 'Warning: '//res%warnings(j)%s)
        end do
        call hangs_part(c, fit, prob)
        call figure_part(c, fit, prob)
        call cert_write(c, outdir//'/'//d%name//'.certificate.html', cert_now(), files, stat)
    end subroutine write_page

    !> The tensor, the principal moments with U, k and the coverage, the axes.
    subroutine result_part(c, res, fit, u_x_mc, u_moments_mc)
        type(certificate_t), intent(inout) :: c
        type(tensor_result_t), intent(in) :: res
        type(tensor_fit_t), intent(in) :: fit
        real(dp), intent(in) :: u_x_mc(6), u_moments_mc(3)
        real(dp) :: j3(3, 3)
        integer :: k
        call cert_section(c, 'Result')
        call cert_text(c, 'The inertia tensor about the mass centre in the body frame of the '// &
            'table of hangs (mass x length^2 in the deck''s units; the products of inertia '// &
            'J_xy = -∫ x y dm).  The principal moments carry U = k u with k for a coverage of '// &
            '95 % (Student''s t at their effective degrees of freedom, Welch-Satterthwaite).')
        j3 = reshape([fit%x(1), fit%x(4), fit%x(5), fit%x(4), fit%x(2), fit%x(6), fit%x(5), &
                      fit%x(6), fit%x(3)], [3, 3])
        call cert_table(c, 'J'//CELL//'x'//CELL//'y'//CELL//'z')
        do k = 1, 3
            call cert_row(c, achar(iachar('x') + k - 1)//CELL//trim(sci(j3(k, 1), 5))//CELL// &
                          trim(sci(j3(k, 2), 5))//CELL//trim(sci(j3(k, 3), 5)))
        end do
        call cert_table(c, 'entry'//CELL//'value'//CELL//'standard u'//CELL// &
                        pick('Monte Carlo u', '-', res%mc_samples > 0))
        do k = 1, 6
            call cert_row(c, NAMES(k)//CELL//trim(sci(fit%x(k), 6))//CELL// &
                          trim(sci(fit%u_x(k), 3))//CELL// &
                          pick(trim(sci(u_x_mc(k), 3)), '-', res%mc_samples > 0))
        end do
        call cert_table(c, 'principal moment'//CELL//'value'//CELL//'standard u'//CELL//'k'// &
                        CELL//'U (95 %)'//CELL//'dof'//CELL//'axis (x, y, z)'//CELL// &
                        'u of the axis (deg)')
        do k = 1, 3
            call cert_row(c, 'I_'//itoa(k)//CELL//trim(sci(fit%moments(k), 6))//CELL// &
                          trim(sci(fit%u_moments(k), 3))//CELL//fixed(fit%k95(k), 2)//CELL// &
                          trim(sci(fit%k95(k)*fit%u_moments(k), 2))//CELL// &
                          trim(dof_text(fit%nu_eff(k)))//CELL//fixed(fit%axes(1, k), 4)//', '// &
                          fixed(fit%axes(2, k), 4)//', '//fixed(fit%axes(3, k), 4)//CELL// &
                          fixed(fit%u_axes(k), 2))
        end do
        if (res%mc_samples > 0) call cert_text(c, 'Monte Carlo ('//itoa(res%mc_samples)// &
            ' samples): u of the principal moments '//trim(sci(u_moments_mc(1), 2))//', '// &
            trim(sci(u_moments_mc(2), 2))//', '//trim(sci(u_moments_mc(3), 2))//'.')
    end subroutine result_part

    !> The mass centre the hangs assumed (an input of this fit).
    subroutine centre_part(c, d, prob)
        type(certificate_t), intent(inout) :: c
        type(deck_t), intent(in) :: d
        type(tensor_problem_t), intent(in) :: prob
        integer :: h
        if (d%suspension%cables > 2) then
            call platform_centre_part(c, d, prob)
            return
        end if
        call cert_section(c, 'Mass centre')
        if (d%tensor%cg_given) then
            call cert_text(c, 'The mass centre in the body frame, as the deck gives it '// &
                '(&tensor cg); each hang''s depth below the strings'' lower ends and offset '// &
                'along them follow from it and the attachment points.')
            call cert_table(c, 'coordinate'//CELL//'value')
            do h = 1, 3
                call cert_row(c, achar(iachar('x') + h - 1)//CELL//trim(sci(d%tensor%cg(h), 5)))
            end do
        else
            call cert_text(c, 'The mass centre as each hang gives it: its depth below the '// &
                'midpoint of the strings'' lower ends and its offset along them.  With up and '// &
                'along the mass centre is taken to lie in the vertical plane of the strings.')
        end if
        call cert_table(c, 'hang'//CELL//'cg_depth'//CELL//'cg_offset')
        do h = 1, size(prob%hangs)
            call cert_row(c, itoa(prob%hangs(h)%id)//CELL//trim(sci(prob%hangs(h)%cg_depth, 4))// &
                          CELL//trim(sci(clean(prob%hangs(h)%cg_offset, prob%hangs(h)%b_prime), &
                          4)))
        end do
    end subroutine centre_part

    !> The mass centre the hangs on a platform assumed: from the platform's centre (the
    !! centroid of the cables' lower ends), along its x and y, and its depth below the
    !! plane of those ends.
    subroutine platform_centre_part(c, d, prob)
        type(certificate_t), intent(inout) :: c
        type(deck_t), intent(in) :: d
        type(tensor_problem_t), intent(in) :: prob
        integer :: h
        call cert_section(c, 'Mass centre')
        if (d%tensor%cg_given) then
            call cert_text(c, 'The mass centre in the body frame, as the deck gives it '// &
                '(&tensor cg); each hang''s offsets from the platform''s centre and depth '// &
                'below its attachment plane follow from it, the hang''s up and along.')
            call cert_table(c, 'coordinate'//CELL//'value')
            do h = 1, 3
                call cert_row(c, achar(iachar('x') + h - 1)//CELL//trim(sci(d%tensor%cg(h), 5)))
            end do
        else
            call cert_text(c, 'The mass centre as each hang gives it, measured from the '// &
                'platform''s centre (the centroid of the cables'' lower ends): cg_offset along '// &
                'the platform''s x axis '//pick('(that of its points, body_points)', &
                '(toward the first cable)', d%suspension%pointwise())//', cg_offset_y along '// &
                'its y axis '// &
                '(up x along), cg_depth below the attachment plane (the plane of the cables'' '// &
                'lower ends; negative: above it, a body resting on the platform).')
        end if
        call cert_table(c, 'hang'//CELL//'cg_offset (x)'//CELL//'cg_offset_y (y)'//CELL// &
                        'cg_depth')
        do h = 1, size(prob%hangs)
            call cert_row(c, itoa(prob%hangs(h)%id)//CELL// &
                          trim(sci(clean(prob%hangs(h)%cg_offset, prob%hangs(h)%b_prime), 4))// &
                          CELL//trim(sci(clean(prob%hangs(h)%cg_offset_y, &
                          prob%hangs(h)%b_prime), 4))//CELL// &
                          trim(sci(prob%hangs(h)%cg_depth, 4)))
        end do
    end subroutine platform_centre_part

    !> The body and the rig as measured, with every input's u.
    subroutine rig_part(c, d, prob)
        type(certificate_t), intent(inout) :: c
        type(deck_t), intent(in) :: d
        type(tensor_problem_t), intent(in) :: prob
        real(dp) :: v(6)
        character(len=24), parameter :: WHAT(6) = [character(len=24) :: 'mass', &
            'l', 'l''', 'b (at the support)', 'b'' (at the body)', 'g']
        integer :: k
        if (d%suspension%cables > 2) then
            call platform_rig_part(c, d, prob)
            return
        end if
        call cert_section(c, 'Body and rig as measured')
        v = [prob%mass, d%suspension%l, d%suspension%l_prime, d%suspension%b, &
             d%suspension%b_prime, prob%g]
        call cert_table(c, 'quantity'//CELL//'value'//CELL//'standard u')
        do k = 1, 6
            call cert_row(c, trim(WHAT(k))//CELL//trim(sci(v(k), 6))//CELL// &
                          trim(sci(d%tensor%u(k), 2)))
        end do
        call cert_row(c, 'u of a timing (s)'//CELL//'-'//CELL//trim(sci(d%tensor%u(7), 2)))
        call cert_row(c, 'u of an amplitude (deg)'//CELL//'-'//CELL//trim(sci(d%tensor%u(8), 2)))
        call cert_row(c, 'u of a direction (deg, each rotation)'//CELL//'-'//CELL// &
                      trim(sci(d%tensor%u_direction, 2)))
        if (any(prob%hangs(1)%own)) call cert_text(c, 'Some hangs give their own l, l'', b or '// &
            'b'' in the table: those are in the table of hangs below.')
    end subroutine rig_part

    !> The body and the platform as measured, with every input's u: its cables, radii R
    !! (support) and R' (platform) and length l, or its points as the deck gives them.
    subroutine platform_rig_part(c, d, prob)
        type(certificate_t), intent(inout) :: c
        type(deck_t), intent(in) :: d
        type(tensor_problem_t), intent(in) :: prob
        integer :: i, n
        call cert_section(c, 'Body and rig as measured')
        n = d%suspension%cables
        if (d%suspension%pointwise()) then
            call cert_text(c, 'A platform of '//itoa(n)//' cables given point by point '// &
                '(&suspension support_points, body_points, lengths): each cable''s point on '// &
                'the support (support''s frame), on the platform (platform''s frame) and its '// &
                'length.  The u of R and R'' apply to the scale of the support''s and the '// &
                'platform''s points about their centroids.')
            call cert_table(c, 'cable'//CELL//'support point'//CELL//'platform point'//CELL// &
                            'length')
            do i = 1, n
                call cert_row(c, itoa(i)//CELL//point_text(d%suspension%support_points(:, i))// &
                              CELL//point_text(d%suspension%body_points(:, i))//CELL// &
                              trim(sci(d%suspension%lengths(i), 6)))
            end do
        else
            call cert_text(c, 'A platform of '//itoa(n)//' cables of length l at the corners '// &
                'of regular polygons: radius R on the support, R'' on the platform (from each '// &
                'polygon''s centre to a cable''s end).')
        end if
        call cert_table(c, 'quantity'//CELL//'value'//CELL//'standard u')
        call cert_row(c, 'cables'//CELL//itoa(n)//CELL//'-')
        call cert_row(c, 'mass (the body)'//CELL//trim(sci(prob%mass, 6))//CELL// &
                      trim(sci(d%tensor%u(1), 2)))
        call cert_row(c, pick('l (mean of the lengths)', 'l (every cable)', &
                      d%suspension%pointwise())//CELL//trim(sci(d%suspension%l, 6))//CELL// &
                      trim(sci(d%tensor%u(2), 2)))
        call cert_row(c, pick('R (mean, at the support)', 'R (radius, at the support)', &
                      d%suspension%pointwise())//CELL//trim(sci(0.5_dp*d%suspension%b, 6))// &
                      CELL//trim(sci(0.5_dp*d%tensor%u(4), 2)))
        call cert_row(c, pick('R'' (mean, at the platform)', 'R'' (radius_prime, at the '// &
                      'platform)', d%suspension%pointwise())//CELL// &
                      trim(sci(0.5_dp*d%suspension%b_prime, 6))//CELL// &
                      trim(sci(0.5_dp*d%tensor%u(5), 2)))
        call cert_row(c, 'g'//CELL//trim(sci(prob%g, 6))//CELL//trim(sci(d%tensor%u(6), 2)))
        call cert_row(c, 'u of a timing (s)'//CELL//'-'//CELL//trim(sci(d%tensor%u(7), 2)))
        call cert_row(c, 'u of an amplitude (deg)'//CELL//'-'//CELL//trim(sci(d%tensor%u(8), 2)))
        call cert_row(c, 'u of a direction (deg, each rotation)'//CELL//'-'//CELL// &
                      trim(sci(d%tensor%u_direction, 2)))
        if (d%tensor%fixture_mass > 0.0_dp) call cert_text(c, 'The platform itself (mass '// &
            trim(sci(d%tensor%fixture_mass, 4))//', its mass centre and inertia in the '// &
            'platform''s axes) is the fixture of every hang (&tensor fixture_*).')
        if (any(prob%hangs(1)%own)) call cert_text(c, 'Some hangs give their own l in the '// &
            'table: those are in the table of hangs below.')
    end subroutine platform_rig_part

    !> A point as 'x, y, z'.
    function point_text(p) result(s)
        real(dp), intent(in) :: p(3)
        character(len=:), allocatable :: s
        s = trim(sci(p(1), 4))//', '//trim(sci(p(2), 4))//', '//trim(sci(p(3), 4))
    end function point_text

    !> The method and the model.
    subroutine method_part(c, d, res, fit, prob)
        type(certificate_t), intent(inout) :: c
        type(deck_t), intent(in) :: d
        type(tensor_result_t), intent(in) :: res
        type(tensor_fit_t), intent(in) :: fit
        type(tensor_problem_t), intent(in) :: prob
        call cert_section(c, 'Method and model')
        if (d%suspension%cables > 2) then
            call cert_text(c, 'The body lay on the platform of three cables in '// &
                itoa(size(prob%hangs))//' orientations (table '//trim(d%tensor%hangs)//'), '// &
                itoa(size(prob%rows))//' timings.  Each hang''s period is that of the '// &
                'torsion of the platform''s own model (three inextensible cables; the '// &
                'platform with its mass, mass centre and inertia a fixture of every hang, '// &
                'the body''s mass centre where it sits, off the axis included) at its '// &
                'amplitude, so the coupling of torsion with sway and tilt is in the fit.  '// &
                'The six entries are fitted to every timing by weighted least squares, '// &
                'started at the projection solution of the linear formula; first-order '// &
                'uncertainties from the inputs'' u (GUM), '//itoa(fit%iterations)// &
                ' iterations; the timing''s u '//pick('stated', 'from the scatter', &
                .not. fit%scatter)//'.')
        else
            call cert_text(c, 'The body hung on the bifilar rig in '//itoa(size(prob%hangs))// &
                ' orientations (table '//trim(d%tensor%hangs)//'), '//itoa(size(prob%rows))// &
                ' timings.  Each hang''s period is that of the torsion mode of the model of T. R. '// &
                'Kane and C. Tseng (1966) of that hang at its amplitude, so the coupling of '// &
                'torsion with tilting and sway when the vertical is not a principal axis is in '// &
                'the fit.  The six entries are fitted to every timing by weighted least squares '// &
                '(each hang''s timings correlated through its own inputs), started at the '// &
                'projection solution of the linear formula; first-order uncertainties from the '// &
                'inputs'' u (GUM), '//itoa(fit%iterations)//' iterations; the timing''s u '// &
                pick('stated', 'from the scatter', .not. fit%scatter)//'.')
        end if
        if (res%mc_samples > 0) call cert_text(c, 'A Monte Carlo of '// &
            itoa(res%mc_samples)//' samples (seed '//itoa(d%tensor%seed)//') draws every '// &
            'input from its u and refits.')
    end subroutine method_part

    !> The budget, sorted by each row's root sum of squares over the six entries.
    subroutine budget_part(c, fit)
        type(certificate_t), intent(inout) :: c
        type(tensor_fit_t), intent(in) :: fit
        integer, allocatable :: order(:)
        real(dp), allocatable :: size_of(:)
        integer :: i, j, k
        character(len=:), allocatable :: row
        call cert_section(c, 'Uncertainty budget')
        if (.not. allocated(fit%budget)) return
        if (size(fit%budget) == 0) then
            call cert_text(c, 'No input carries an uncertainty.')
            return
        end if
        call cert_text(c, 'Each input''s standard uncertainty (a direction in degrees) and '// &
            'what it adds to the u of each entry; the rows sorted by their size over the six '// &
            'entries (root sum of squares), the largest first.')
        size_of = [(norm2(fit%budget(i)%contribution), i=1, size(fit%budget))]
        order = [(i, i=1, size(fit%budget))]
        do i = 2, size(order)               ! insertion sort, largest first
            k = order(i)
            j = i - 1
            do while (j >= 1)
                if (size_of(order(j)) >= size_of(k)) exit
                order(j + 1) = order(j)
                j = j - 1
            end do
            order(j + 1) = k
        end do
        call cert_table(c, 'input'//CELL//'standard u'//CELL//NAMES(1)//CELL//NAMES(2)//CELL// &
                        NAMES(3)//CELL//NAMES(4)//CELL//NAMES(5)//CELL//NAMES(6))
        do i = 1, size(order)
            associate (r => fit%budget(order(i)))
                row = trim(r%input)//CELL//trim(sci(r%u, 2))
                do j = 1, 6
                    row = row//CELL//trim(sci(r%contribution(j), 2))
                end do
                call cert_row(c, row)
            end associate
        end do
        row = 'u (root sum of squares)'//CELL//'-'
        do j = 1, 6
            row = row//CELL//trim(sci(fit%u_x(j), 2))
        end do
        call cert_row(c, row)
    end subroutine budget_part

    !> Every check with its value.
    subroutine checks_part(c, res, fit, prob, drift, limit, u_moments_mc)
        type(certificate_t), intent(inout) :: c
        type(tensor_result_t), intent(in) :: res
        type(tensor_fit_t), intent(in) :: fit
        type(tensor_problem_t), intent(in) :: prob
        real(dp), intent(in) :: drift(:), limit(:), u_moments_mc(3)
        real(dp) :: tri, ang
        call cert_section(c, 'Checks')
        call cert_table(c, 'check'//CELL//'value'//CELL//'what it says')
        call cert_row(c, 'positive definite: smallest / largest moment'//CELL// &
                      trim(sci(fit%moments(1)/fit%moments(3), 3))//CELL// &
                      pick('positive: a body can have it', 'not positive', &
                                 fit%moments(1) > 0.0_dp))
        tri = fit%moments(3)/(fit%moments(1) + fit%moments(2))
        call cert_row(c, 'triangle: I_3 / (I_1 + I_2)'//CELL//fixed(tri, 4)//CELL// &
                      'at most 1 for a rigid body (1: a lamina); refused above '// &
                      fixed(TRIANGLE_MARGIN, 2)//', a warning between')
        if (fit%dof > 0) then
            call cert_row(c, 'fit: chi^2 (dof)'//CELL//trim(sci(fit%chi2, 3))//' ('// &
                          itoa(fit%dof)//')'//CELL//'p = '//trim(sci(fit%p_value, 2))//': '// &
                          pick('consistent', 'inconsistent', &
                               fit%p_value >= 0.05_dp .or. fit%scatter)// &
                          pick(' (u from the scatter)', '', fit%scatter))
        else
            call cert_row(c, 'fit: chi^2'//CELL//trim(sci(fit%chi2, 3))//CELL// &
                          'no degree of freedom: not tested')
        end if
        call cert_row(c, 'fit: largest normalised residual'//CELL// &
                      trim(sci(maxval(abs(fit%resid)), 3))//CELL//'per hang, measured - fitted '// &
                      'vertical moment over its u')
        call cert_row(c, 'projection solution: distance / I_3'//CELL// &
                      trim(sci(res%projection_difference, 3))//CELL//'the linear formula''s '// &
                      'tensor against the fitted one')
        call cert_row(c, 'directions: condition number'//CELL//trim(sci(fit%condition, 3))// &
                      CELL//'of the hangs'' design matrix; large: directions nearly dependent')
        ang = smallest_angle(prob)
        call cert_row(c, 'directions: smallest angle between two hangs (deg)'//CELL// &
                      fixed(ang, 2)//CELL//pick('below the warning''s '//fixed( &
                      NEAR_PARALLEL_DEG, 1)//' deg: near-parallel', 'apart: each hang a '// &
                      'direction of its own', ang < NEAR_PARALLEL_DEG))
        if (size(drift) > 0) call cert_row(c, 'periods'' definition: largest drift'//CELL// &
            trim(sci(maxval(drift), 2))//CELL//'of the maxima over the first cycles; at most '// &
            trim(sci(DRIFT_MAX, 1))//' (smallest amplitude limit '// &
            trim(sci(minval(limit), 2))//' deg)')
        if (res%mc_samples > 0) call cert_row(c, 'Monte Carlo u / first-order u (I_3)'// &
            CELL//fixed(u_moments_mc(3)/max(fit%u_moments(3), tiny(1.0_dp)), 3)//CELL// &
            'near 1: the first order holds')
        call cert_row(c, 'warnings'//CELL//itoa(size(res%warnings) + &
                      merge(1, 0, len(res%warning) > 0))//CELL//'listed below')
    end subroutine checks_part

    !> The smallest angle between two hangs' up directions (u and -u as one; degrees).
    pure real(dp) function smallest_angle(prob) result(a)
        type(tensor_problem_t), intent(in) :: prob
        integer :: i, j
        a = 90.0_dp
        do i = 1, size(prob%hangs)
            do j = i + 1, size(prob%hangs)
                if (prob%hangs(i)%id == prob%hangs(j)%id) cycle
                a = min(a, acos(min(1.0_dp, abs(dot_product(prob%hangs(i)%up, &
                                                             prob%hangs(j)%up))))/deg)
            end do
        end do
    end function smallest_angle

    !> The hangs as timed (the inputs) with their u, and what each gives.
    subroutine hangs_part(c, fit, prob)
        type(certificate_t), intent(inout) :: c
        type(tensor_fit_t), intent(in) :: fit
        type(tensor_problem_t), intent(in) :: prob
        integer :: h, i
        call cert_section(c, 'Hangs')
        call cert_table(c, 'hang'//CELL//'up (body frame)'//CELL// &
                        pick('along (the platform''s x)', 'along (C to D)', &
                        prob%hangs(1)%cables > 2)//CELL// &
                        'vertical moment measured'//CELL//'its u'//CELL//'fitted'//CELL// &
                        'normalised residual')
        do h = 1, size(prob%hangs)
            associate (g => prob%hangs(h))
                call cert_row(c, itoa(g%id)//CELL//vec(g%up)//CELL//vec(g%along)//CELL// &
                              trim(sci(fit%iv(h), 5))//CELL//trim(sci(fit%u_iv(h), 2))//CELL// &
                              trim(sci(fit%iv_fit(h), 5))//CELL//fixed(fit%resid(h), 2))
            end associate
        end do
        call cert_table(c, 'timing'//CELL//'hang'//CELL//'period per cycle (s)'//CELL// &
                        'cycles'//CELL//'amplitude (deg)'//CELL//'u of the period (s)'//CELL// &
                        'model''s period (s)')
        do i = 1, size(prob%rows)
            associate (r => prob%rows(i))
                call cert_row(c, itoa(i)//CELL//itoa(prob%hangs(r%release)%id)//CELL// &
                              trim(sci(r%period, 7))//CELL//trim(sci(r%cycles, 3))//CELL// &
                              trim(sci(r%amplitude, 3))//CELL//trim(sci(row_u(fit, r%u_period, &
                              i), 2))//CELL//trim(sci(fit%model_period(i), 7)))
            end associate
        end do
    end subroutine hangs_part

    !> The u of row i's period the fit used (the stated one when the fit has none).
    pure real(dp) function row_u(fit, stated, i) result(u)
        type(tensor_fit_t), intent(in) :: fit
        real(dp), intent(in) :: stated
        integer, intent(in) :: i
        u = stated
        if (allocated(fit%u_row)) then
            if (i <= size(fit%u_row)) u = fit%u_row(i)
        end if
    end function row_u

    !> The figure: each hang's measured vertical moment with its u, and the fitted tensor's.
    subroutine figure_part(c, fit, prob)
        type(certificate_t), intent(inout) :: c
        type(tensor_fit_t), intent(in) :: fit
        type(tensor_problem_t), intent(in) :: prob
        type(svg_plot_t) :: p
        real(dp), allocatable :: x(:)
        integer :: h
        call cert_section(c, 'Figure')
        x = [(real(h, dp), h=1, size(prob%hangs))]
        p = svg_new('Vertical moment of each hang', 'hang (in the table''s order)', &
                    'moment about the vertical')
        call svg_add(p, x, fit%iv_fit, 'fitted tensor: u . J u', color='#1f4e9c', points=.true.)
        call svg_add(p, x, fit%iv, 'measured (its periods)', color='#c0392b', points=.true., &
                     err=fit%u_iv)
        call cert_figure(c, svg_render(p), 'Each hang''s moment about the vertical: what its '// &
                         'periods give (with its u) and what the fitted tensor gives.')
    end subroutine figure_part

    !> x, or 0 when below roundoff against the length `scale`.
    pure real(dp) function clean(x, scale)
        real(dp), intent(in) :: x, scale
        clean = merge(0.0_dp, x, abs(x) <= 1.0e-12_dp*abs(scale))
    end function clean

    !> A unit vector as text.
    function vec(v) result(s)
        real(dp), intent(in) :: v(3)
        character(len=:), allocatable :: s
        s = fixed(v(1), 3)//', '//fixed(v(2), 3)//', '//fixed(v(3), 3)
    end function vec

    !> a when cond, else b.
    pure function pick(a, b, cond) result(s)
        character(len=*), intent(in) :: a, b
        logical, intent(in) :: cond
        character(len=:), allocatable :: s
        if (cond) then
            s = a
        else
            s = b
        end if
    end function pick

    pure function dof_text(nu) result(s)
        real(dp), intent(in) :: nu
        character(len=24) :: s
        if (nu >= NU_INFINITE) then
            s = '∞'
        else
            s = fixed(nu, 1)
        end if
    end function dof_text

end submodule tensor_certificate
