!> The water on the demo slide (inputs/demo_slide/slide.nml, ~67 m) as the
!> scenario builds it from inputs/water/demo_slide.nml:
!> - Saint-Venant correction full vs off: the largest difference of the
!>   water-middle angle v along the slide is reported (the thesis, fig. 4.14,
!>   found it negligible) and must stay well below the ~1 rad range of v;
!> - continuity A(h, R) w = Q with the correction on: on a curved slide R moves
!>   with beta, so this holds only if dR/dt (F.5) is the true rate of R;
!> - energy: loss = work of friction + work of the Saint-Venant term.
program test_water_demo_slide
  use base_kinds, only: wp
  use base_status, only: status_t
  use io_input, only: input_text_t, load_input_file
  use water_run, only: water_description_t, new_streamline
  use testing, only: check, finish_tests
  use water_streamline, only: streamline_t, CORRECTION_FULL, CORRECTION_OFF, CORRECTION_NO_RADIUS
  use water_flow, only: water_series_t, simulate_water, OUTCOME_END
  use scenarios_water, only: build_water
  implicit none (type, external)

  type(water_series_t) :: full, off, no_radius
  real(wp) :: dv_max, s_at, cerr, e_err, loss
  integer :: i, j, k_at

  call run(CORRECTION_FULL, full)
  call run(CORRECTION_OFF, off)
  call run(CORRECTION_NO_RADIUS, no_radius)

  ! compare at equal arc length (the two flows pass a station at different times)
  dv_max = 0; s_at = 0; k_at = 1
  j = 1
  do i = 1, full%n
    do while (j < off%n - 1 .and. off%arc_length(j + 1) < full%arc_length(i))
      j = j + 1
    end do
    if (full%arc_length(i) < off%arc_length(1) .or. full%arc_length(i) > off%arc_length(off%n)) cycle
    associate (lam => (full%arc_length(i) - off%arc_length(j))/(off%arc_length(j + 1) - off%arc_length(j)))
      if (abs(full%v(i) - ((1 - lam)*off%v(j) + lam*off%v(j + 1))) > dv_max) then
        dv_max = abs(full%v(i) - ((1 - lam)*off%v(j) + lam*off%v(j + 1)))
        s_at = full%arc_length(i); k_at = i
      end if
    end associate
  end do
  print '(a, f8.5, a, f6.2, a, f7.3, a)', '  Saint-Venant full vs off: largest difference of the water-middle angle ', &
    dv_max, ' rad (', dv_max*57.29577951308232_wp, ' deg) at arc length ', s_at, ' m'
  print '(a, f8.5, a)', '  range of v along the slide (full): ', maxval(full%v(:full%n)) - minval(full%v(:full%n)), ' rad'
  call check(dv_max < 0.2_wp*(maxval(full%v(:full%n)) - minval(full%v(:full%n))), &
             'the correction changes the water-middle angle by a small fraction of its range')

  cerr = maxval(abs(full%area(:full%n)*full%speed(:full%n) - full%flow_rate))/full%flow_rate
  ! 1e-8: h (~1e-2 m) integrated with atol 1e-12 over ~1e4 steps; dR/dt off by 10 % gives 3e-3
  call check(cerr <= 1e-8_wp, 'demo slide: continuity A(h, R) w = Q with R moving')
  print '(a, es10.2)', '  continuity error (full): ', cerr
  cerr = maxval(abs(no_radius%area(:no_radius%n)*no_radius%speed(:no_radius%n) - no_radius%flow_rate)) &
         /no_radius%flow_rate
  call check(cerr <= 1e-8_wp, 'demo slide: continuity also without the radius term in kappa')
  e_err = 0
  do i = 1, full%n
    loss = (full%kinetic(1) + full%potential(1)) - (full%kinetic(i) + full%potential(i))
    e_err = max(e_err, abs(loss + full%friction_work(i) + full%correction_work(i)) &
                /abs(full%friction_work(full%n)))
  end do
  call check(e_err <= 1e-8_wp, 'demo slide: energy loss = friction work + Saint-Venant work')
  print '(a, 2es10.2)', '  continuity error (no radius term), energy error (full): ', cerr, e_err
  call finish_tests('test_water_demo_slide')

contains

  subroutine run(correction, s)
    integer, intent(in) :: correction
    type(water_series_t), intent(out) :: s
    type(input_text_t) :: input
    type(water_description_t) :: description
    type(streamline_t), target :: model
    type(status_t) :: st
    real(wp) :: y0(7)
    call load_input_file('inputs/water/demo_slide.nml', input, st)
    call check(st%ok(), 'demo input read')
    call build_water(input, description, st)
    if (st%ok()) call new_streamline(description, model, y0, st)
    call check(st%ok(), 'demo model built: '//st%text())
    if (.not. st%ok()) return
    model%correction = correction
    description%solver%ode%rtol = 1e-12_wp; description%solver%ode%atol = 1e-12_wp
    call simulate_water(model, y0, description%solver%ode, description%solver%time_bound, 0.01_wp, s, st, edges=.false.)
    call check(st%ok() .and. s%outcome == OUTCOME_END, 'demo slide: the water reaches the end')
    ! the arc length summed sample by sample (3-point Gauss) against the whole quadrature
    call check(abs(s%arc_length(s%n) - model%channel%arc_length(s%u(s%n))) <= 1e-9_wp*s%arc_length(s%n), &
               'demo slide: incremental arc length')
  end subroutine run
end program test_water_demo_slide
