!> The period of a platform of four or more cables from its elastic cables' periodic torsion
!! (module platform_elastic_orbit: &cables stiffness, Radau IIA at the accuracy's rtol and
!! atol).  A submodule of platform_measure, so that the modules using platform_measure stay
!! below the elastic orbit's floor.
submodule (platform_measure) platform_measure_elastic
    use platform_elastic_orbit, only: elastic_torsion_period
    implicit none
contains

    module subroutine elastic_period_s(rg, acc, amp_deg, t, stat)
        type(rig_t), intent(in) :: rg
        type(accuracy_t), intent(in) :: acc
        real(dp), intent(in) :: amp_deg
        real(dp), intent(out) :: t
        type(status_t), intent(out) :: stat
        call elastic_torsion_period(platform_of_rig(rg), rg%cable_stiffness, amp_deg*deg, &
                                    acc%rtol, acc%atol, t, stat)
        if (stat%code /= STATUS_OK) stat%msg = 'the period at '//fixed(amp_deg, 3)// &
            ' deg (the elastic platform''s periodic torsion): '//stat%msg
    end subroutine elastic_period_s

end submodule platform_measure_elastic
