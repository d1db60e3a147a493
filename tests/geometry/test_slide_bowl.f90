!> The bowl as an element of the slide chain (issue 26; the point mass
!> circling inside a spherical and a conical bowl against the closed form is
!> test_slide_parts' bowl_circles, on the surfaces of revolution themselves).
!>
!> geometry: a straight, a bowl (spherical, then conical) and an outlet
!> straight. Across every joint and every end of the bowl's windows the
!> centerline's position, unit tangent and curvature vector are continuous to
!> 1e-9 relative; each derivative (to the fourth) matches central differences
!> of the one below; between its windows the centerline lies on the bowl's
!> surface of revolution about one vertical axis (distance from the axis
!> rho(sigma) = rho_in - sigma sin(beta) and height f(rho) above one bottom, to
!> 1e-9 m), crossing the circles at the angle beta of `turns` turns, the
!> wall's slope at the entry is the one asked and the outlet is as deep as
!> the drop asked; impossible bowls are refused with a message naming why.
!>
!> heading alone: the chain's heading (what its quadrature of x and y
!> evaluates, eight times per evaluation) is the evaluation's to the bit,
!> cos and sin of it equal the unit tangent's x and y exactly, on a chain
!> with a drop, a curve, a bowl of each profile and their windows.
!>
!> arc length table: the chain's arc length from its start (the whole panels
!> from a table) is the quadrature's without the table to the bit, at every
!> 10 cm, at the panels' ends and three roundings either side, beyond the
!> end, backwards and from another start.
!>
!> normal force: a frictionless point mass on the slide (flume section)
!> slides across the bowl's joints: the normal force changes between 1 ms
!> records by little (no jump); with transitions of 2 cm it jumps at the
!> joints (the check can fail).
program test_slide_bowl
  use base_kinds, only: wp
  use base_constants, only: pi, two_pi, standard_gravity
  use base_status, only: status_t
  use base_vector, only: cross
  use geometry_curve, only: curve_point_t
  use geometry_slide_elements, only: slide_element_t, element_chain_curve_t, new_element_chain
  use geometry_curve, only: panel_arc_length
  use numerics_ode, only: ode_integrator_t
  use kinetostatics_point_mass, only: point_mass_t, point_mass_state_t
  use io_input, only: input_text_t, input_from_text
  use io_solver_config, only: solver_config_t
  use scenarios_point_mass, only: build_point_mass
  use scenario_fixtures, only: joint_jumps, start_point_mass, real_text
  use testing, only: check, check_close, finish_tests
  implicit none (type, external)

  character(len=*), parameter :: nl = new_line('a')
  real(wp), parameter :: rho_in = 6, entry_deg = 50, depth = 2, turns = 1   ! m, deg, m, 1

  call bowl_geometry('sphere')
  call bowl_geometry('cone')
  call bowl_refusals()
  call bowl_at_the_ends()
  call bowl_normal_force()
  call bowl_self_intersection()
  call heading_alone()
  call arc_length_table()
  call finish_tests('test_slide_bowl')

contains

  !> Straight, bowl of `profile`, straight, with transitions of `transition` m.
  function bowl_chain(profile, transition, status) result(chain)
    character(len=*), intent(in) :: profile
    real(wp), intent(in) :: transition
    type(status_t), intent(out) :: status
    type(element_chain_curve_t) :: chain
    type(slide_element_t) :: e(3)
    e(1) = slide_element_t(kind='straight', length=8.0_wp, slope_deg=10.0_wp)
    e(2) = slide_element_t(kind='bowl', bowl_profile=profile, radius=rho_in, slope_deg=entry_deg, drop=depth, &
                           turns=turns, direction='right')
    e(3) = slide_element_t(kind='straight', length=6.0_wp, slope_deg=8.0_wp)
    chain = new_element_chain(e, [0.0_wp, 0.0_wp, 12.0_wp], 30.0_wp, transition, status)
  end function bowl_chain

  subroutine bowl_geometry(profile)
    character(len=*), intent(in) :: profile
    type(element_chain_curve_t) :: chain
    type(status_t) :: st
    type(curve_point_t) :: p, q, r
    real(wp) :: marks(6), jump(3), x, worst, centre(2), bottom, rho, f_rho, s_a, s_b, tol_scale, e_rho(2), ang, &
                beta, t_xy(2), z_a, z_b
    integer :: i, n
    chain = bowl_chain(profile, 2.0_wp, st)
    call check(st%ok(), profile//' bowl chain built: '//st%text())
    if (.not. st%ok()) return
    call check(size(chain%bowls) == 1, profile//': one bowl')
    associate (b => chain%bowls(1))
      ! the joints and the ends of the bowl's windows
      marks = [b%lo, b%sigma0, b%sigma0 + b%width_in/2, b%sigma0 + b%length - b%width_out/2, &
               b%sigma0 + b%length, b%hi]
      call check(b%width_in > 0 .and. b%width_out > 0 .and. marks(4) > marks(3), profile//': the bowl has its windows')
      call joint_jumps(chain, marks, 1/b%rho_out, jump)
      call check(jump(1) <= 1e-9_wp, profile//' bowl joints: position continuous to 1e-9')
      call check(jump(2) <= 1e-9_wp, profile//' bowl joints: unit tangent continuous to 1e-9')
      call check(jump(3) <= 1e-9_wp, profile//' bowl joints: curvature continuous to 1e-9 of 1/rho_out')
      ! each derivative against central differences of the one below, at
      ! scattered points over the bowl and its windows (h = 1e-5 m:
      ! truncation ~h^2 c''''' ~1e-9, rounding ~eps/h ~1e-11 of the values)
      worst = 0
      do i = 1, 41
        x = b%lo + (b%hi - b%lo)*(i - 0.37_wp)/41
        call chain%evaluate(x, 4, p, st)
        call chain%evaluate(x + 1e-5_wp, 4, q, st)
        call chain%evaluate(x - 1e-5_wp, 4, r, st)
        do n = 1, 4
          worst = max(worst, norm2((q%d(:, n - 1) - r%d(:, n - 1))/2e-5_wp - p%d(:, n))/max(norm2(p%d(:, n)), 1.0_wp))
        end do
      end do
      call check(worst <= 1e-6_wp, profile//' bowl: derivatives against central differences: '//real_text(worst))
      ! between the windows: on the surface of revolution about one axis. The
      ! plan's tangent t = cos(beta) e_phi - sin(beta) e_rho (inward at beta),
      ! so e_rho is t turned by -(90 deg + beta) for a left bowl, + for a right one
      beta = asin(b%sin_beta)
      call check_close(two_pi*turns, b%cos_beta/b%sin_beta*log(b%rho_in/b%rho_out), 1e-13_wp, 0.0_wp, &
                       profile//': cot(beta) ln(rho_in/rho_out) = 2 pi turns')
      s_a = marks(3)
      s_b = marks(4)
      worst = 0
      tol_scale = 0
      do i = 0, 20
        x = s_a + (s_b - s_a)*i/20.0_wp
        call chain%evaluate(x, 1, p, st)
        rho = b%radius_at(x)
        t_xy = p%d(1:2, 1)/norm2(p%d(1:2, 1))
        ang = -b%sense*(pi/2 + beta)
        e_rho = [cos(ang)*t_xy(1) - sin(ang)*t_xy(2), sin(ang)*t_xy(1) + cos(ang)*t_xy(2)]
        f_rho = b%height_above_bottom(rho)
        if (i == 0) then
          centre = p%d(1:2, 0) - rho*e_rho
          bottom = p%d(3, 0) - f_rho
        end if
        worst = max(worst, norm2(p%d(1:2, 0) - rho*e_rho - centre), abs(p%d(3, 0) - f_rho - bottom))
      end do
      call check(worst <= 1e-9_wp, profile//' bowl: the centerline between the windows lies on the surface of '// &
                 'revolution about one axis (to 1e-9 m): '//real_text(worst))
      ! the wall's slope at the entry and the outlet's depth below it
      if (profile == 'sphere') then
        call check_close(b%rho_in/b%sphere_radius, sin(entry_deg*pi/180), 1e-14_wp, 0.0_wp, &
                         profile//': the wall rises at the slope asked at the entry')
      else
        call check_close(b%tan_wall, tan(entry_deg*pi/180), 1e-14_wp, 0.0_wp, profile//': the cone''s wall slope')
      end if
      z_a = b%height_above_bottom(b%rho_in)
      z_b = b%height_above_bottom(b%rho_out)
      call check_close(z_a - z_b, depth, 1e-12_wp, 0.0_wp, profile//': the outlet lies the drop asked below the entry')
      ! the gradient there is the spiral's: sin(beta) f'(rho)
      call chain%evaluate(0.5_wp*(s_a + s_b), 1, p, st)
      rho = b%radius_at(0.5_wp*(s_a + s_b))
      if (profile == 'sphere') then
        f_rho = rho/sqrt(b%sphere_radius**2 - rho**2)
      else
        f_rho = b%tan_wall
      end if
      call check_close(-p%d(3, 1), b%sin_beta*f_rho, 1e-12_wp, 0.0_wp, profile//': the gradient sin(beta) f''(rho)')
    end associate
  end subroutine bowl_geometry

  !> A bowl that begins and one that ends the chain: no window there, the
  !> spiral itself up to the chain's end, derivatives included (the curvature's
  !> rate at sigma = 0 and at the end as just inside).
  subroutine bowl_at_the_ends()
    type(element_chain_curve_t) :: chain
    type(status_t) :: st
    type(curve_point_t) :: p, q
    real(wp) :: kappa_rate(2)
    integer :: side
    do side = 1, 2
      if (side == 1) then
        chain = new_element_chain([slide_element_t(kind='bowl', radius=rho_in, slope_deg=entry_deg, drop=depth, &
                                                   turns=turns), &
                                   slide_element_t(kind='straight', length=6.0_wp, slope_deg=8.0_wp)], &
                                  [0.0_wp, 0.0_wp, 12.0_wp], 0.0_wp, 2.0_wp, st)
      else
        chain = new_element_chain([slide_element_t(kind='straight', length=6.0_wp, slope_deg=8.0_wp), &
                                   slide_element_t(kind='bowl', radius=rho_in, slope_deg=entry_deg, drop=depth, &
                                                   turns=turns)], [0.0_wp, 0.0_wp, 12.0_wp], 0.0_wp, 2.0_wp, st)
      end if
      call check(st%ok(), 'a chain that begins or ends with a bowl: '//st%text())
      if (.not. st%ok()) return
      call chain%evaluate(merge(0.0_wp, chain%total, side == 1), 3, p, st)
      call chain%evaluate(merge(1e-9_wp, chain%total - 1e-9_wp, side == 1), 3, q, st)
      ! the plan's curvature rate d(kappa)/dsigma = x' y''' - y' x''' (|c'_xy| = 1, kappa' = 0 there)
      kappa_rate = [p%d(1, 1)*p%d(2, 3) - p%d(2, 1)*p%d(1, 3), q%d(1, 1)*q%d(2, 3) - q%d(2, 1)*q%d(1, 3)]
      call check(abs(kappa_rate(1)) > 1e-3_wp .and. abs(kappa_rate(1) - kappa_rate(2)) <= 1e-9_wp*abs(kappa_rate(1)), &
                 'the bowl''s curvature rate at the chain''s '//trim(merge('start', 'end  ', side == 1))//': '// &
                 real_text(kappa_rate(1))//' and just inside '//real_text(kappa_rate(2)))
    end do
  end subroutine bowl_at_the_ends

  subroutine bowl_refusals()
    ! the drop reaches the bottom (sphere: depth below the entry R (1 - cos 50 deg) = 2.8 m)
    call refused('sphere', 2.9_wp, entry_deg, 1.0_wp, 2.0_wp, 'reaches the bottom of the spherical bowl')
    ! the cone's apex 6 tan(50 deg) = 7.2 m below the entry
    call refused('cone', 7.5_wp, entry_deg, 1.0_wp, 2.0_wp, 'reaches the apex of the conical bowl')
    call refused('sphere', depth, 90.0_wp, 1.0_wp, 2.0_wp, 'rim of a hemisphere')
    call refused('bucket', depth, entry_deg, 1.0_wp, 2.0_wp, 'is not one of sphere, cone')
    ! 0.02 turns down an 80 deg wall: the spiral itself descends at ~68 deg
    call refused('cone', depth, 80.0_wp, 0.02_wp, 2.0_wp, 'steeper than')
    call refused('sphere', depth, entry_deg, 1.0_wp, 0.0_wp, 'transition_length = 0 makes joint 1')
    call refused('cone', 7.0_wp, entry_deg, 1.0_wp, 2.0_wp, 'would carry its spiral to the axis')
  end subroutine bowl_refusals

  subroutine refused(profile, drop, slope, n_turns, transition, words)
    character(len=*), intent(in) :: profile, words
    real(wp), intent(in) :: drop, slope, n_turns, transition
    type(element_chain_curve_t) :: chain
    type(status_t) :: st
    type(slide_element_t) :: e(2)
    e(1) = slide_element_t(kind='straight', length=8.0_wp, slope_deg=10.0_wp)
    e(2) = slide_element_t(kind='bowl', bowl_profile=profile, radius=rho_in, slope_deg=slope, drop=drop, &
                           turns=n_turns)
    chain = new_element_chain([e, slide_element_t(kind='straight', length=20.0_wp, slope_deg=8.0_wp)], &
                              [0.0_wp, 0.0_wp, 12.0_wp], 0.0_wp, transition, st)
    call check(.not. st%ok() .and. index(st%text(), words) > 0, 'refused ('//words//'): '//st%text())
  end subroutine refused

  !> A frictionless point mass from the entry straight's bottom line into the
  !> bowl and out: the largest change of N between 1 ms records (per kg, in
  !> units of g) with transitions of 2 m and of 2 cm (shorter ones fold the
  !> tube at the outlet's change of slope, which the tube's check may miss
  !> between its samples).
  subroutine bowl_normal_force()
    real(wp) :: smooth, sharp
    call slide_across('2.0', smooth)
    call slide_across('0.02', sharp)
    print '(a, es10.3, a, es10.3, a)', 'largest change of N between records: ', smooth, ' g (2 m transitions), ', &
      sharp, ' g (2 cm)'
    ! smooth: at the outlet (v ~ 9 m/s, kappa 0.29 1/m -> 0 over w = 2 m)
    ! the transition changes N by at most 35/16 v^3 dkappa/w ~ 230 m/s^3, 0.025 g
    ! per 1 ms record, and the mass's swing across the flume (omega ~
    ! sqrt(30/0.8) 1/s on N ~ 30 m/s^2 per kg) ~0.02 g more: bound 0.1 g. A sharp
    ! joint changes N by the mass's v^2 kappa up the wall, ~2 g, within
    ! 2 ms at 9 m/s over 2 cm
    call check(smooth <= 0.1_wp, 'no jump of the normal force across the bowl''s joints: '//real_text(smooth)//' g')
    call check(sharp >= 0.5_wp, 'nearly sharp bowl joints: the normal force jumps (the check can fail): '// &
               real_text(sharp)//' g (smooth '//real_text(smooth)//' g)')
  end subroutine bowl_normal_force

  subroutine slide_across(transition, jump)
    character(len=*), intent(in) :: transition
    real(wp), intent(out) :: jump
    type(point_mass_t), target :: model
    type(ode_integrator_t) :: integrator
    type(point_mass_state_t) :: state
    type(status_t) :: st
    real(wp), allocatable :: y0(:)
    real(wp) :: y(5), t, n_prev, u_end
    integer :: k
    logical :: at_root, started
    type(element_chain_curve_t) :: chain
    chain = bowl_chain('sphere', 2.0_wp, st)
    u_end = chain%ends(2) + 1.5_wp   ! past the outlet's joint and its window (+- 1 m)
    jump = huge(1.0_wp)
    call start_point_mass(point_mass_input(transition, '1'), 'bowl point mass ('//transition//')', model, &
                          integrator, y0, state, started)
    if (.not. started) return
    jump = 0
    n_prev = state%normal_force
    do k = 1, 20000
      call integrator%advance(1e-3_wp*k, t, y, st, root_found=at_root)
      if (.not. st%ok() .or. at_root) exit
      call model%state(y, state, st)
      jump = max(jump, abs(state%normal_force - n_prev)/standard_gravity)
      n_prev = state%normal_force
      if (y(1) >= u_end) exit
    end do
    call check(st%ok() .and. .not. at_root, 'bowl point mass ran ('//transition//'): '//st%text())
    call check(y(1) >= u_end, 'the mass crossed the bowl''s joints ('//transition//')')
    call integrator%destroy()
  end subroutine slide_across

  !> The point mass on the bowl chain of bowl_chain('sphere', ...) with a
  !> flume section (radius 0.8 m, walls 0.6 m: 1 m to either side).
  function point_mass_input(transition, bowl_turns) result(text)
    character(len=*), intent(in) :: transition, bowl_turns
    character(len=:), allocatable :: text
    text = '&run scenario = ''point_mass'' /'//nl// &
      '&solver method = ''adams'', rtol = 1e-10, atol = 1e-10 /'//nl// &
      '&surface kind = ''slide'' /'//nl//'&geometry kind = ''slide'' /'//nl// &
      '&slide_elements n_elements = 3, start = 0, 0, 12, heading_deg = 30, transition_length = '//transition// &
      ', centerline_kind = ''exact'', kind = ''straight'', ''bowl'', ''straight'', length = 8, 0, 2.5,'// &
      ' slope_deg = 6, 50, 2.5, radius = 0, 6, 0, drop = 0, 2, 0, turns = 0, '//bowl_turns//', 0,'// &
      ' direction = ''left'', ''right'', ''left'' /'//nl// &
      '&cross_section kind = ''flume'', radius = 0.8, wall = 0.6 /'//nl// &
      '&point_mass u0 = 0.5, v0 = 1.5707963267948966, du0 = 6, dv0 = 0, friction = ''none'' /'
  end function point_mass_input

  !> The global self-intersection check on a bowl: 1.25 turns leave 2.04 m
  !> between the turns of the spiral, about the flume's 2 m width (and less
  !> where the spiral's slope tilts the gap): refused, naming the two places;
  !> 1 turn (2.56 m) passes (slide_across).
  subroutine bowl_self_intersection()
    type(input_text_t) :: input
    type(solver_config_t) :: solver
    type(point_mass_t), target :: model
    type(status_t) :: st
    real(wp), allocatable :: y0(:)
    call input_from_text('<test>', point_mass_input('2.0', '1.25'), input, st)
    if (st%ok()) call build_point_mass(input, solver, model, y0, st)
    call check(.not. st%ok() .and. index(st%text(), 'the tube passes through itself') > 0, &
               'a bowl whose turns overlap is refused by the self-intersection check: '//st%text())
  end subroutine bowl_self_intersection

  !> chain%heading against the tangent of chain%evaluate, bit for bit, at
  !> every 1 mm of two chains (a drop, a curve, a spherical bowl, a straight;
  !> a conical bowl between straights) and at the ends of every window.
  subroutine heading_alone()
    type(slide_element_t) :: e(4)
    type(element_chain_curve_t) :: chain
    type(status_t) :: st
    real(wp) :: u_min, u_max
    integer :: i, k, mismatches, points
    e(1) = slide_element_t(kind='drop', slope_deg=80.0_wp, radius=8.0_wp, drop=10.0_wp)
    e(2) = slide_element_t(kind='curve', slope_deg=4.0_wp, radius=12.0_wp, angle_deg=90.0_wp)
    e(3) = slide_element_t(kind='bowl', radius=rho_in, slope_deg=entry_deg, drop=depth, turns=turns)
    e(4) = slide_element_t(kind='straight', length=6.0_wp, slope_deg=8.0_wp)
    mismatches = 0
    points = 0
    do k = 1, 2
      if (k == 1) then
        chain = new_element_chain(e, [0.0_wp, 0.0_wp, 20.0_wp], 0.0_wp, 2.0_wp, st)
      else
        chain = bowl_chain('cone', 1.5_wp, st)
      end if
      call check(st%ok(), 'heading alone: chain built: '//st%text())
      if (.not. st%ok()) return
      call chain%domain(u_min, u_max)
      do i = 0, floor((u_max - u_min)/1e-3_wp)
        call compare_heading(chain, u_min + i*1e-3_wp, points, mismatches)
      end do
      do i = 1, size(chain%bowls)
        associate (b => chain%bowls(i))
          call compare_heading(chain, b%lo, points, mismatches)
          call compare_heading(chain, b%core_lo, points, mismatches)
          call compare_heading(chain, b%core_hi, points, mismatches)
          call compare_heading(chain, b%hi, points, mismatches)
          call compare_heading(chain, b%node(1), points, mismatches)
          call compare_heading(chain, 0.5_wp*(b%lo + b%core_lo), points, mismatches)
        end associate
      end do
    end do
    call check(points > 20000 .and. mismatches == 0, 'heading alone: the evaluation''s tangent is cos and sin '// &
               'of chain%heading to the bit ('//real_text(real(mismatches, wp))//' of '// &
               real_text(real(points, wp))//' points differ)')
  end subroutine heading_alone

  subroutine arc_length_table()
    type(element_chain_curve_t) :: chain
    type(status_t) :: st
    real(wp) :: lo, hi, u, width
    integer :: i, j, mismatches, points
    chain = bowl_chain('sphere', 2.0_wp, st)
    call check(st%ok() .and. allocated(chain%arc_prefix), 'arc length table: chain built: '//st%text())
    if (.not. st%ok()) return
    call chain%domain(lo, hi)
    width = (hi - lo)/256
    mismatches = 0
    points = 0
    do i = 0, floor((hi - lo)/0.1_wp) + 10   ! to 1 m beyond the end
      call compare_arc_length(chain, lo, lo + i*0.1_wp, points, mismatches)
      call compare_arc_length(chain, lo + i*0.1_wp, lo, points, mismatches)   ! backwards: negative
      call compare_arc_length(chain, lo + 0.3_wp, lo + i*0.1_wp, points, mismatches)   ! another start
    end do
    do i = 0, 256
      u = lo + i*width
      call compare_arc_length(chain, lo, u, points, mismatches)
      do j = 1, 3
        call compare_arc_length(chain, lo, u + j*spacing(u), points, mismatches)
        call compare_arc_length(chain, lo, u - j*spacing(u), points, mismatches)
      end do
    end do
    call check(points > 2000 .and. mismatches == 0, 'arc length table: the chain''s arc length is the quadrature''s '// &
               'without the table to the bit ('//real_text(real(mismatches, wp))//' of '// &
               real_text(real(points, wp))//' differ)')
  end subroutine arc_length_table

  subroutine compare_arc_length(chain, u0, u1, points, mismatches)
    type(element_chain_curve_t), intent(in) :: chain
    real(wp), intent(in) :: u0, u1
    integer, intent(inout) :: points, mismatches
    points = points + 1
    if (.not. chain%arc_length(u0, u1) == panel_arc_length(chain, u0, u1)) mismatches = mismatches + 1
  end subroutine compare_arc_length

  subroutine compare_heading(chain, at, points, mismatches)
    type(element_chain_curve_t), intent(in) :: chain
    real(wp), intent(in) :: at
    integer, intent(inout) :: points, mismatches
    type(curve_point_t) :: p
    type(status_t) :: st
    real(wp) :: psi
    call chain%evaluate(at, 1, p, st)
    psi = chain%heading(at)
    points = points + 1
    if (.not. (st%ok() .and. cos(psi) == p%d(1, 1) .and. sin(psi) == p%d(2, 1))) mismatches = mismatches + 1
  end subroutine compare_heading
end program test_slide_bowl
