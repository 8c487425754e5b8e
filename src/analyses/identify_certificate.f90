!> The certificate of an `identify` run: OUTDIR/NAME.certificate.html, one self-contained
!! page for A4 (module certificate) that an engineer can attach to a test report.  It holds
!! the title; the body and the rig as measured, with every input's value and standard
!! uncertainty; the method and the model; the result I1 +- U with k, the coverage and the
!! effective degrees of freedom; the budget sorted by contribution, with each row's share
!! of u_I1^2; every check with its value (the fit's consistency, chi^2 and the Birge ratio,
!! the residuals, the releases' consistency, the classical formula's gap, the tare, the
!! calibration, the Monte Carlo); the warnings; the figure (periods against amplitude with
!! the model's curve, or the record with the model and the residuals); and, at its foot,
!! the program's version, the deck's CRC-64 and the date.
submodule (identify) identify_certificate
    use text, only: itoa, sci, fixed
    use stats, only: NU_INFINITE
    use crc64, only: crc64_of, hex16
    use version, only: BIFILAR_VERSION
    use svg_plot, only: svg_plot_t, svg_new, svg_add, svg_render
    use certificate, only: certificate_t, cert_new, cert_section, cert_text, cert_table, &
        cert_row, cert_figure, cert_write, cert_note, cert_now, CELL
    implicit none

contains

    !> Write OUTDIR/NAME.certificate.html for an identify run into the run's files.
    module procedure write_identify_certificate
        type(certificate_t) :: c
        character(len=:), allocatable :: crc
        crc = '(none)'
        if (allocated(d%text)) crc = hex16(crc64_of(d%text))
        c = cert_new('Moment of inertia I1 about the vertical axis', trim(d%scene%title), &
                     BIFILAR_VERSION, d%path, crc)
        call result_section(c, d, res)
        call rig_section(c, d)
        call method_section(c, d, res)
        call budget_section(c, res)
        call checks_section(c, d, res)
        call figure_section(c, fig)
        if (res%n_trials > 1) call releases_section(c, res)
        call cert_write(c, outdir//'/'//d%name//'.certificate.html', cert_now(), files, stat)
    end procedure write_identify_certificate

    !> The result: I1 +- U, k, the coverage, dof_eff; the other parameters.
    subroutine result_section(c, d, res)
        type(certificate_t), intent(inout) :: c
        type(deck_t), intent(in) :: d
        type(identify_result_t), intent(in) :: res
        integer :: j
        call cert_section(c, 'Result')
        call cert_text(c, 'I1 = '//trim(sci(res%i1, 5))//' ± '//trim(sci(res%u_i1_expanded, 2))// &
                       ' (mass x length^2 in the deck''s units), the expanded uncertainty U = k u '// &
                       'with k = '//fixed(res%k, 2)//' for a coverage of 95 % (Student''s t at '// &
                       trim(dof_text(res%dof_eff))//' effective degrees of freedom, '// &
                       'Welch-Satterthwaite); the standard uncertainty u_I1 = '// &
                       trim(sci(res%u_i1, 2))//'.')
        if (.not. res%uncertainty_given) call cert_note(c, 'No uncertainty of any input was '// &
            'given and the data could not show one: u_I1 = 0 says nothing about the result.')
        call cert_table(c, 'quantity'//CELL//'value'//CELL//'standard u')
        call cert_row(c, 'I1 (the body)'//CELL//trim(sci(res%i1, 6))//CELL//trim(sci(res%u_i1, 3)))
        if (d%measurement%tare_i1 > 0.0_dp .or. d%measurement%added_inertia > 0.0_dp .or. &
            res%i1_tare_file > 0.0_dp) &
            call cert_row(c, 'I1 of all that hung'//CELL//trim(sci(res%i1_total, 6))//CELL// &
                          trim(sci(res%u_i1_total, 3)))
        do j = 2, res%np
            call cert_row(c, trim(res%names(j))//CELL//trim(sci(res%p(j), 5))//CELL// &
                          trim(sci(res%u_p(j), 2)))
        end do
        if (d%measurement%monte_carlo > 0 .and. res%u_i1_mc >= 0.0_dp) &
            call cert_row(c, 'I1, Monte Carlo mean ('//itoa(d%measurement%monte_carlo)// &
                          ' samples)'//CELL//trim(sci(res%mc_mean, 6))//CELL// &
                          trim(sci(res%u_i1_mc, 3)))
    end subroutine result_section

    !> The body and the rig as measured: each input with its value and u.
    subroutine rig_section(c, d)
        type(certificate_t), intent(inout) :: c
        type(deck_t), intent(in) :: d
        integer :: j
        call cert_section(c, 'Body and rig as measured')
        associate (s => d%suspension, b => d%body, m => d%measurement)
            if (s%cables >= 3) then
                call cert_text(c, 'A platform hung from '//itoa(s%cables)//' cables.')
            else
                call cert_text(c, 'A body hung from two cables (a bifilar pendulum); b and b'' '// &
                               'are the full distances between the cables at the support and at '// &
                               'the body.')
            end if
            call cert_table(c, 'input'//CELL//'value'//CELL//'standard u')
            call cert_row(c, 'mass'//CELL//trim(sci(b%mass, 6))//CELL//trim(sci(m%u_mass, 2)))
            call cert_row(c, 'l (cable length)'//CELL//trim(sci(s%l, 6))//CELL//trim(sci(m%u_l, 2)))
            call cert_row(c, 'l'' (second cable)'//CELL//trim(sci(s%l_prime, 6))//CELL// &
                          trim(sci(m%u_l_prime, 2)))
            if (s%cables >= 3) then
                call cert_row(c, 'R (support radius)'//CELL//trim(sci(s%radius, 6))//CELL//'-')
                call cert_row(c, 'R'' (platform radius)'//CELL//trim(sci(s%radius_prime, 6))// &
                              CELL//'-')
            else
                call cert_row(c, 'b (at the support)'//CELL//trim(sci(s%b, 6))//CELL// &
                              trim(sci(m%u_b, 2)))
                call cert_row(c, 'b'' (at the body)'//CELL//trim(sci(s%b_prime, 6))//CELL// &
                              trim(sci(m%u_b_prime, 2)))
            end if
            call cert_row(c, 'g'//CELL//trim(sci(s%g, 6))//CELL//trim(sci(m%u_g, 2)))
            call cert_row(c, 'cg_depth'//CELL//trim(sci(b%cg_depth, 4))//CELL// &
                          trim(sci(m%u_cg_depth, 2)))
            if (m%n_periods > 0) then
                call cert_row(c, 'u of a timing (period)'//CELL//'-'//CELL//trim(sci(m%u_period, 2)))
                call cert_row(c, 'u of an amplitude (deg)'//CELL//'-'//CELL// &
                              trim(sci(m%u_amplitude, 2)))
                do j = 1, m%n_periods
                    call cert_row(c, 'timing '//itoa(j)//': '//trim(cycles_text(m%cycles(j)))// &
                                  ' at '//trim(sci(m%amplitudes(j), 3))//' deg'//CELL// &
                                  trim(sci(m%periods(j), 6))//CELL//trim(sci(m%u_period, 2)))
                end do
            end if
            if (m%tare_i1 > 0.0_dp .or. m%u_tare_i1 > 0.0_dp) &
                call cert_row(c, 'tare I1 (subtracted)'//CELL//trim(sci(m%tare_i1, 6))//CELL// &
                              trim(sci(m%u_tare_i1, 2)))
            if (len_trim(m%tare) > 0) &
                call cert_row(c, 'tare (subtracted): its own output '//trim(m%tare)//CELL// &
                              'its I1'//CELL//'its budget: the shared inputs once')
            if (m%tare_mass > 0.0_dp) &
                call cert_row(c, 'tare mass'//CELL//trim(sci(m%tare_mass, 6))//CELL//'-')
            if (m%added_inertia > 0.0_dp .or. m%u_added_inertia > 0.0_dp) &
                call cert_row(c, 'added inertia (subtracted)'//CELL// &
                              trim(sci(m%added_inertia, 6))//CELL//trim(sci(m%u_added_inertia, 2)))
            if (len_trim(m%record) > 0) call cert_text(c, 'Record: '//trim(m%record)// &
                ' (quantity '//trim(m%quantity)//').')
            if (len_trim(m%trials) > 0) call cert_text(c, 'Table of releases: '//trim(m%trials)//'.')
        end associate
    end subroutine rig_section

    !> The method and the model.
    subroutine method_section(c, d, res)
        type(certificate_t), intent(inout) :: c
        type(deck_t), intent(in) :: d
        type(identify_result_t), intent(in) :: res
        character(len=:), allocatable :: how
        call cert_section(c, 'Method and model')
        if (res%from_record) then
            how = 'The record of the swing was fitted, sample by sample, with the full '// &
                  'nonlinear motion of the rig (T. R. Kane and G.-T. Tseng, "Dynamics of the '// &
                  'bifilar pendulum", 1966) integrated from the release; the parameters fitted: '// &
                  trim(d%measurement%estimate)//'.'
        else
            how = 'Each timed period was inverted through the period of the rig''s torsion at '// &
                  'its amplitude ('//trim(res%period_model)//' periods of the model of T. R. Kane '// &
                  'and G.-T. Tseng, "Dynamics of the bifilar pendulum", 1966), not through the '// &
                  'small-angle formula; I1 is the least-squares value over the timings.'
        end if
        call cert_text(c, how)
        call cert_text(c, 'Uncertainty: first-order propagation of every input''s standard '// &
                       'uncertainty through the whole fit (GUM, JCGM 100:2008), the sensitivities '// &
                       'of the fit to each input; the coverage factor from Student''s t at the '// &
                       'Welch-Satterthwaite degrees of freedom.  The fit checks itself: chi^2 of '// &
                       'its residuals against their stated u; when improbable (p < 0.05) its '// &
                       'covariance is scaled up by the Birge ratio squared.')
        if (d%measurement%monte_carlo > 0) call cert_text(c, 'A Monte Carlo of '// &
            itoa(d%measurement%monte_carlo)//' samples (GUM Supplement 1, seed '// &
            itoa(d%measurement%seed)//') checks the first-order u.')
    end subroutine method_section

    !> The budget, sorted by contribution, with each row's share of u_I1^2.
    subroutine budget_section(c, res)
        type(certificate_t), intent(inout) :: c
        type(identify_result_t), intent(in) :: res
        integer, allocatable :: order(:)
        integer :: i, j, k
        real(dp) :: total
        call cert_section(c, 'Uncertainty budget of I1')
        if (.not. allocated(res%budget)) return
        if (size(res%budget) == 0) then
            call cert_text(c, 'No input carries an uncertainty.')
            return
        end if
        order = [(i, i=1, size(res%budget))]
        do i = 2, size(order)               ! insertion sort, largest contribution first
            k = order(i)
            j = i - 1
            do while (j >= 1)
                if (res%budget(order(j))%contribution >= res%budget(k)%contribution) exit
                order(j + 1) = order(j)
                j = j - 1
            end do
            order(j + 1) = k
        end do
        total = sum(res%budget%contribution**2)
        call cert_table(c, 'input'//CELL//'value'//CELL//'standard u'//CELL//'sensitivity'// &
                        CELL//'contribution'//CELL//'share of u^2 (%)')
        do i = 1, size(order)
            associate (r => res%budget(order(i)))
                call cert_row(c, trim(r%input)//CELL//trim(sci(r%value, 5))//CELL// &
                              trim(sci(r%u, 2))//CELL//trim(sci(r%sensitivity, 3))//CELL// &
                              trim(sci(r%contribution, 2))//CELL// &
                              fixed(100.0_dp*r%contribution**2/max(total, tiny(1.0_dp)), 1))
            end associate
        end do
        call cert_row(c, 'u_I1 (root sum of squares)'//CELL//'-'//CELL//'-'//CELL//'-'//CELL// &
                      trim(sci(sqrt(total), 2))//CELL//'100.0')
    end subroutine budget_section

    !> Every check with its value.
    subroutine checks_section(c, d, res)
        type(certificate_t), intent(inout) :: c
        type(deck_t), intent(in) :: d
        type(identify_result_t), intent(in) :: res
        integer :: j
        call cert_section(c, 'Checks')
        call cert_table(c, 'check'//CELL//'value'//CELL//'what it says')
        call cert_row(c, 'residual rms'//CELL//trim(sci(res%residual_rms, 3))//CELL// &
                      trim(merge('rad or rad/s, as recorded', 's                        ', &
                                 res%from_record)))
        if (res%from_record) then
            call cert_row(c, 'record: effective samples'//CELL//trim(sci(res%n_effective, 3))//CELL// &
                          'samples / correlation time of the residuals')
            call cert_row(c, 'record: sigma'//CELL//trim(sci(res%sigma, 3))//CELL// &
                          trim(merge('stated  ', 'residual', res%sigma_stated)))
        else if (res%u_period_scatter >= 0.0_dp) then
            call cert_row(c, 'u of a timing from the scatter'//CELL// &
                          trim(sci(res%u_period_scatter, 3))//CELL//'no u_period was given')
        end if
        call cert_row(c, 'releases pooled'//CELL//itoa(res%n_trials)//CELL//trim(res%consistency))
        if (res%birge_ratio >= 0.0_dp) then
            call cert_row(c, 'releases: Birge ratio'//CELL//fixed(res%birge_ratio, 3)//CELL// &
                          'chi^2 p = '//trim(sci(res%p_value, 2)))
            call cert_row(c, 'u from the releases'' scatter'//CELL// &
                          trim(sci(res%u_i1_reproducibility, 2))//CELL//'in u_I1')
        end if
        call cert_row(c, 'classical formula'//CELL//trim(sci(res%i1_linear, 5))//CELL// &
                      'gap '//trim(sci(res%linear_error, 2))//' (the amplitude correction)')
        call cert_row(c, 'fit iterations'//CELL//itoa(res%iterations)//CELL//'converged')
        if (d%measurement%tare_i1 > 0.0_dp) &
            call cert_row(c, 'tare'//CELL//trim(sci(d%measurement%tare_i1, 4))//CELL// &
                          fixed(100.0_dp*d%measurement%tare_i1/max(res%i1_total, tiny(1.0_dp)), 1)// &
                          ' % of all that hung')
        if (res%i1_tare_file > 0.0_dp) &
            call cert_row(c, 'tare (from its output)'//CELL//trim(sci(res%i1_tare_file, 4))// &
                          CELL//fixed(100.0_dp*res%i1_tare_file/max(res%i1_total, &
                          tiny(1.0_dp)), 1)//' % of all that hung; same rig, shared inputs '// &
                          'correlated')
        if (len_trim(d%measurement%calibration) > 0) then
            call cert_row(c, 'calibration'//CELL//trim(d%measurement%calibration)//CELL// &
                          'the rig''s constants from it; its covariance is the budget''s '// &
                          'row calibration')
        else
            call cert_row(c, 'calibration'//CELL//'none'//CELL//'the rig''s constants as measured')
        end if
        if (d%measurement%monte_carlo > 0 .and. res%u_i1_mc >= 0.0_dp) &
            call cert_row(c, 'Monte Carlo u / first-order u'//CELL// &
                          fixed(res%u_i1_mc/max(res%u_i1, tiny(1.0_dp)), 3)//CELL// &
                          'near 1: the first order holds')
        call cert_row(c, 'warnings'//CELL//itoa(size(res%warnings))//CELL//'listed below')
        do j = 1, size(res%warnings)
            call cert_note(c, 'Warning: '//res%warnings(j)%s)
        end do
    end subroutine checks_section

    !> The figure.
    subroutine figure_section(c, fig)
        type(certificate_t), intent(inout) :: c
        type(cert_figure_data_t), intent(in) :: fig
        type(svg_plot_t) :: p
        if (.not. (fig%periods .or. fig%record)) return
        call cert_section(c, 'Figures')
        if (fig%periods) then
            p = svg_new('Periods against amplitude', 'amplitude (deg)', 'period per cycle (s)')
            if (allocated(fig%curve_amp)) then
                call svg_add(p, fig%curve_amp, fig%curve_per, 'model at I1', color='#1f4e9c')
                call svg_add(p, fig%curve_amp, spread(fig%classical, 1, size(fig%curve_amp)), &
                             'classical formula', color='#999999')
            end if
            call svg_add(p, fig%amp, fig%per, 'timed', color='#c0392b', points=.true., &
                         err=fig%u_per)
            call cert_figure(c, svg_render(p), 'The timed periods (per cycle, with their u) '// &
                             'and the model''s period at the fitted I1; the classical formula''s '// &
                             'period does not depend on the amplitude.')
        else
            p = svg_new('The record and the model', 't (s)', fig%units)
            call svg_add(p, fig%t, fig%measured, 'measured', color='#c0392b')
            call svg_add(p, fig%t, fig%model, 'model', color='#1f4e9c')
            call cert_figure(c, svg_render(p), 'The record and the fitted model.')
            p = svg_new('Residuals', 't (s)', fig%units, height=220)
            call svg_add(p, fig%t, fig%measured - fig%model, 'measured - model', color='#555555')
            call cert_figure(c, svg_render(p), 'The residuals: a pattern in them is a model '// &
                             'that does not follow the record.')
        end if
    end subroutine figure_section

    !> The releases, each with its I1 and u.
    subroutine releases_section(c, res)
        type(certificate_t), intent(inout) :: c
        type(identify_result_t), intent(in) :: res
        integer :: j
        call cert_section(c, 'Releases')
        call cert_table(c, 'release'//CELL//'I1 (all that hung)'//CELL//'its own u')
        do j = 1, res%n_trials
            call cert_row(c, trim(res%trial_label(j))//CELL//trim(sci(res%trial_i1(j), 6))// &
                          CELL//trim(sci(res%trial_u(j), 2)))
        end do
    end subroutine releases_section

    pure function dof_text(nu) result(s)
        real(dp), intent(in) :: nu
        character(len=24) :: s
        if (nu >= NU_INFINITE) then
            s = '∞'
        else
            s = fixed(nu, 1)
        end if
    end function dof_text

    pure function cycles_text(n) result(s)
        real(dp), intent(in) :: n
        character(len=32) :: s
        if (n > 0.0_dp .and. n /= 1.0_dp) then
            s = 'total of '//trim(sci(n, 3))//' cycles'
        else
            s = 'one cycle'
        end if
    end function cycles_text


end submodule identify_certificate
