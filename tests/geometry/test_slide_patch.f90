!> The free-form patch as an element of the slide chain (issue 26): a
!> B-spline surface from points laid on the slide's wall along one element
!> (geometry_patch_section).
!>
!> geometry, against known answers:
!> - a patch whose points are all on the slide's circle (offsets 0) is the
!>   plain straight: the slide with the patch and the one with a straight in
!>   its place agree in position and every partial to the third, to 1e-12 m
!>   (exact and fitted centerlines);
!> - offsets from a product of quartics in the station and the angle (0 on
!>   the grid's border): the quintic interpolant reproduces them, so the
!>   wall's distance from the centerline of a level straight is R + W(x) W(a)
!>   d(x, a) everywhere, the windows written here from the smoothstep (1e-12 m);
!> - at both ends of the patch (joints with the elements before and after)
!>   and at the ends of its windows in u and v the surface's position, first
!>   and second derivatives and its normal are continuous to 1e-9 relative
!>   (each side 1e-7 m off carried across by its next derivative), exact and
!>   fitted; every partial matches central differences of the one below
!>   (1e-6 relative);
!> - every partial of the patch's section has the same bits whatever order
!>   of derivatives is asked (0..3): outside the patch, on its windows'
!>   ramps and where both windows are flat (the shortcuts of
!>   patch_offset_at change no number);
!> - over the slide's circle the patch's section (cos v and sin v once for
!>   the circle and the offset's normal) and its extent (from the circle's
!>   points and normals kept at construction) are the general path's (a
!>   circle the patch does not know as one) bit for bit;
!> - impossible patches are refused with a message naming why, and the
!>   global check of the tube sees a patch's bulge (a U-turn whose patch
!>   reaches the straight before it).
!>
!> point mass: sliding frictionless from a curve over the shipped patch
!> (inputs/parts/patch_slide.nml), the energy is kept to 1e-7 and the
!> normal force changes between 1 ms records by little; evaluated just
!> before and just after each end of the patch (1e-9 m apart, the same
!> velocity) it differs by less than 1e-7 g: no jump.
!> A circle that the patch does not know as one: its evaluate, range and
!> extent are the circle's, but over it patch_evaluate takes the general
!> path (the base evaluated, cos v and sin v again) and, as it does not say
!> that it is one section along u, patch_extent evaluates every point.
module test_slide_patch_support
  use base_kinds, only: wp
  use base_status, only: status_t
  use geometry_cross_section, only: cross_section_t, section_point_t, circle_section_t
  implicit none (type, external)
  private
  public :: plain_circle_t

  type, extends(cross_section_t) :: plain_circle_t
    type(circle_section_t) :: circle
  contains
    procedure :: evaluate => plain_evaluate
    procedure :: v_range => plain_range
    procedure :: periodic => plain_periodic
    procedure :: extent => plain_extent
  end type plain_circle_t

contains

  pure subroutine plain_evaluate(self, u, v, order, p, status)
    class(plain_circle_t), intent(in) :: self
    real(wp), intent(in) :: u, v
    integer, intent(in) :: order
    type(section_point_t), intent(out) :: p
    type(status_t), intent(out) :: status
    call self%circle%evaluate(u, v, order, p, status)
  end subroutine plain_evaluate

  pure subroutine plain_range(self, v_min, v_max)
    class(plain_circle_t), intent(in) :: self
    real(wp), intent(out) :: v_min, v_max
    call self%circle%v_range(v_min, v_max)
  end subroutine plain_range

  pure logical function plain_periodic(self) result(periodic)
    class(plain_circle_t), intent(in) :: self
    periodic = self%circle%periodic()
  end function plain_periodic

  pure real(wp) function plain_extent(self, u) result(r)
    class(plain_circle_t), intent(in) :: self
    real(wp), intent(in) :: u
    r = self%circle%extent(u)
  end function plain_extent
end module test_slide_patch_support

program test_slide_patch
  use base_kinds, only: wp
  use base_constants, only: pi, standard_gravity
  use base_status, only: status_t
  use base_vector, only: cross
  use geometry_surface, only: surface_point_t
  use geometry_slide_elements, only: slide_element_t
  use geometry_slide_builder, only: slide_description_t, section_part_description_t, build_slide
  use geometry_patch_section, only: patch_grid_t, patch_section_t, new_patch_section
  use geometry_drop_profile, only: smoothstep
  use geometry_tube, only: tube_surface_t
  use geometry_cross_section, only: section_point_t, circle_section_t
  use test_slide_patch_support, only: plain_circle_t
  use geometry_curve, only: curve_point_t
  use geometry_curve_frame, only: curve_frame_t
  use numerics_ode, only: ode_integrator_t, ode_options_t
  use kinetostatics_point_mass, only: point_mass_t, point_mass_state_t
  use io_input, only: input_text_t, input_from_text
  use io_solver_config, only: solver_config_t
  use scenarios_point_mass, only: build_point_mass
  use testing, only: check, check_close, finish_tests
  implicit none (type, external)

  character(len=*), parameter :: nl = new_line('a')
  real(wp), parameter :: r_slide = 0.6_wp, patch_length = 10, amplitude = 0.08_wp   ! m

  call zero_patch_is_straight(.true.)
  call zero_patch_is_straight(.false.)
  call quartic_patch()
  call patch_continuity(.true.)
  call patch_continuity(.false.)
  call patch_orders_agree()
  call patch_circle_shortcuts()
  call patch_refusals()
  call patch_normal_force()
  call finish_tests('test_slide_patch')

contains

  !> d(x, a) = amplitude P(x) Q(a): quartics 0 at the grid's first and last
  !> station (0, 10 m) and angle (30, 150 deg), 1 at their middle.
  pure real(wp) function quartic(x, a) result(d)
    real(wp), intent(in) :: x, a
    d = amplitude*(x*(patch_length - x)/25)**2*((a - 30)*(150 - a)/3600)**2
  end function quartic

  !> The grid of element `element`: stations 0, 1, ..., 10 m, angles 30, 50,
  !> ..., 150 deg, offsets `scale` times the quartics.
  function quartic_grid(element, scale) result(grid)
    integer, intent(in) :: element
    real(wp), intent(in) :: scale
    type(patch_grid_t) :: grid
    integer :: i, j
    grid%element = element
    grid%station = [(real(i, wp), i=0, 10)]
    grid%angle_deg = [(30 + 20*real(j, wp), j=0, 6)]
    allocate (grid%offset(11, 7))
    do j = 1, 7
      do i = 1, 11
        grid%offset(i, j) = scale*quartic(grid%station(i), grid%angle_deg(j))
      end do
    end do
  end function quartic_grid

  !> Straight, curve, `middle` (a patch of `scale` times the quartics, or a
  !> straight), straight; a circle section.
  function patch_slide(exact, middle, scale) result(d)
    logical, intent(in) :: exact
    character(len=*), intent(in) :: middle
    real(wp), intent(in) :: scale
    type(slide_description_t) :: d
    d%kind = 'slide'
    d%elements%elements = [slide_element_t(kind='straight', length=8.0_wp, slope_deg=8.0_wp), &
                           slide_element_t(kind='curve', radius=6.0_wp, angle_deg=90.0_wp, slope_deg=6.0_wp), &
                           slide_element_t(kind=middle, length=patch_length, slope_deg=3.0_wp), &
                           slide_element_t(kind='straight', length=6.0_wp, slope_deg=6.0_wp)]
    d%elements%start = [0.0_wp, 0.0_wp, 10.0_wp]
    d%elements%transition_length = 2
    d%elements%exact = exact
    allocate (d%elements%patches(0))
    if (middle == 'patch') d%elements%patches = [quartic_grid(3, scale)]
    d%section%parts = [section_part_description_t(kind='circle', radius=r_slide)]
  end function patch_slide

  !> Offsets 0 (every point on the slide's circle): the slide of a straight.
  subroutine zero_patch_is_straight(exact)
    logical, intent(in) :: exact
    type(tube_surface_t) :: patched, plain
    type(surface_point_t) :: p, q
    type(status_t) :: st
    real(wp) :: u0, u1, u, v, worst
    integer :: i, j
    character(len=:), allocatable :: label
    label = merge('exact ', 'fitted', exact)
    call build_slide(patch_slide(exact, 'patch', 0.0_wp), patched, st)
    call check(st%ok(), 'slide with a patch of zero offsets built ('//label//'): '//st%text())
    call build_slide(patch_slide(exact, 'straight', 0.0_wp), plain, st)
    call check(st%ok(), 'slide with a straight built ('//label//'): '//st%text())
    if (.not. st%ok()) return
    call check(same_type_as(patched%section, patch_section_t()), 'the patched slide''s section is a patch''s')
    call plain%domain(u0, u1, v, worst)
    worst = 0
    do i = 0, 200
      u = u0 + (u1 - u0)*i/200
      do j = 0, 24
        v = 2*pi*j/24
        call patched%evaluate(u, v, 3, p, st)
        call plain%evaluate(u, v, 3, q, st)
        worst = max(worst, norm2(p%r - q%r), norm2(p%ru - q%ru), norm2(p%rv - q%rv), norm2(p%ruu - q%ruu), &
                    norm2(p%ruv - q%ruv), norm2(p%rvv - q%rvv), norm2(p%ruuu - q%ruuu), norm2(p%ruuv - q%ruuv), &
                    norm2(p%ruvv - q%ruvv), norm2(p%rvvv - q%rvvv))
      end do
    end do
    print '(a, a, es10.3)', label, ': zero patch against the straight, largest difference: ', worst
    call check(worst <= 1e-12_wp, 'a patch on the slide''s circle is the plain straight ('//label//'): '// &
               real_text(worst))
  end subroutine zero_patch_is_straight

  !> On a level straight chain (u = sigma, the frame's normal plane fixed)
  !> the wall's distance from the centerline is R + W(x) W(a) d(x, a).
  subroutine quartic_patch()
    type(slide_description_t) :: d
    type(tube_surface_t) :: slide
    type(surface_point_t) :: p
    type(curve_frame_t) :: f
    type(curve_point_t) :: c
    type(status_t) :: st
    real(wp) :: x, a, expected, worst, worst_grid
    integer :: i, j
    d%kind = 'slide'
    d%elements%elements = [slide_element_t(kind='straight', length=5.0_wp), &
                           slide_element_t(kind='patch', length=patch_length), &
                           slide_element_t(kind='straight', length=5.0_wp)]
    d%elements%exact = .true.
    d%elements%patches = [quartic_grid(2, 1.0_wp)]
    d%section%parts = [section_part_description_t(kind='circle', radius=r_slide)]
    call build_slide(d, slide, st)
    call check(st%ok(), 'level slide with a quartic patch built: '//st%text())
    if (.not. st%ok()) return
    worst = 0
    worst_grid = 0
    do i = 0, 100
      x = patch_length*i/100
      do j = 0, 72
        a = 5.0_wp*j
        call slide%frame(5 + x, 0, f, st, c)
        call slide%evaluate(5 + x, a*pi/180, 0, p, st)
        expected = r_slide + window(x, [0.0_wp, 1.0_wp, 9.0_wp, 10.0_wp])*window(a, [30.0_wp, 50.0_wp, 130.0_wp, &
                   150.0_wp])*quartic(x, a)
        worst = max(worst, abs(norm2(p%r - c%d(:, 0)) - expected))
        ! at the grid's points the given offset itself (inside the windows)
        if (mod(i, 10) == 0 .and. mod(j, 4) == 2 .and. a >= 30 .and. a <= 150) &
          worst_grid = max(worst_grid, abs(norm2(p%r - c%d(:, 0)) - (r_slide + quartic(x, a))))
      end do
    end do
    print '(a, 2es10.3)', 'quartic patch: largest error of the wall''s distance, everywhere and at the grid: ', &
      worst, worst_grid
    call check(worst <= 1e-12_wp, 'the wall is R + W W d of the quartics (a quintic reproduces them): '// &
               real_text(worst))
    call check(worst_grid <= 1e-12_wp, 'the wall passes through every given point: '//real_text(worst_grid))
  end subroutine quartic_patch

  !> The window of e(1) .. e(4) at x, written from the smoothstep.
  real(wp) function window(x, e) result(w)
    real(wp), intent(in) :: x, e(4)
    real(wp) :: d(0:3), p, s
    call smoothstep((x - e(1))/(e(2) - e(1)), d, p)
    s = d(0)
    call smoothstep((x - e(3))/(e(4) - e(3)), d, p)
    w = s - d(0)
  end function window

  subroutine patch_continuity(exact)
    logical, intent(in) :: exact
    type(tube_surface_t) :: slide
    type(status_t) :: st
    type(surface_point_t) :: p, q
    real(wp) :: ends(4), v_ends(4), u, v, h, worst_jump, worst_v_jump, worst_fd
    character(len=:), allocatable :: label
    integer :: j, k, i
    label = merge('exact ', 'fitted', exact)
    call build_slide(patch_slide(exact, 'patch', 1.0_wp), slide, st)
    call check(st%ok(), 'slide with a patch built ('//label//'): '//st%text())
    if (.not. st%ok()) return
    select type (s => slide%section)
    type is (patch_section_t)
      ends = s%patches(1)%u_ends
      v_ends = s%patches(1)%v_ends
    class default
      call check(.false., 'the slide''s section is a patch section ('//label//')')
      return
    end select
    if (exact) call check(abs(ends(1) - (8 + 6*pi/2)) < 1e-12_wp .and. abs(ends(4) - ends(1) - patch_length) &
                          < 1e-12_wp, 'the patch lies on its element (exact: u = sigma)')
    worst_jump = 0
    do k = 1, 4
      do j = 0, 12
        v = 2*pi*j/12
        h = 1e-7_wp
        call slide%evaluate(ends(k) - h, v, 3, p, st)
        call slide%evaluate(ends(k) + h, v, 3, q, st)
        worst_jump = max(worst_jump, rel(p%r + 2*h*p%ru, q%r), rel(p%ru + 2*h*p%ruu, q%ru), &
                         rel(p%ruu + 2*h*p%ruuu, q%ruu), rel(p%rv + 2*h*p%ruv, q%rv), &
                         rel(unit(cross(p%ru + 2*h*p%ruu, p%rv + 2*h*p%ruv)), unit(cross(q%ru, q%rv))))
      end do
    end do
    worst_v_jump = 0
    do k = 1, 4
      do j = 1, 9
        u = ends(1) + (ends(4) - ends(1))*j/10
        h = 1e-7_wp
        call slide%evaluate(u, v_ends(k) - h, 3, p, st)
        call slide%evaluate(u, v_ends(k) + h, 3, q, st)
        worst_v_jump = max(worst_v_jump, rel(p%r + 2*h*p%rv, q%r), rel(p%rv + 2*h*p%rvv, q%rv), &
                           rel(p%rvv + 2*h*p%rvvv, q%rvv), rel(p%ru + 2*h*p%ruv, q%ru), &
                           rel(unit(cross(p%ru + 2*h*p%ruv, p%rv + 2*h*p%rvv)), unit(cross(q%ru, q%rv))))
      end do
    end do
    print '(a, a, 2es10.3)', label, ': largest jump at the patch''s ends in u, in v (r, 1st, 2nd, normal): ', &
      worst_jump, worst_v_jump
    ! carried across 2h = 2e-7 by the next derivative, what is left is
    ! (2 h)^2/2 times the one after (~1e-13 here) or a jump
    call check(worst_jump <= 1e-9_wp, 'the patch''s ends along the slide are C2 ('//label//'): '// &
               real_text(worst_jump))
    call check(worst_v_jump <= 1e-9_wp, 'the patch''s edges around the section are C2 ('//label//'): '// &
               real_text(worst_v_jump))
    worst_fd = 0
    do i = 1, 8
      u = ends(1) + (ends(4) - ends(1))*(i - 0.5_wp)/8
      do j = 1, 7
        v = (20 + 20*j)*pi/180
        call fd_errors(slide, u, v, worst_fd)
      end do
    end do
    print '(a, a, es10.3)', label, ': largest derivative error against differences: ', worst_fd
    call check(worst_fd <= 1e-6_wp, 'the patch''s derivatives against differences ('//label//'): '// &
               real_text(worst_fd))
  end subroutine patch_continuity

  !> The largest relative error of the partials at (u, v) against central
  !> differences of the order below (h = 1e-5: truncation h^2 ~ 1e-10
  !> relative, rounding 1e-16/1e-5).
  subroutine fd_errors(slide, u, v, worst)
    type(tube_surface_t), intent(in) :: slide
    real(wp), intent(in) :: u, v
    real(wp), intent(inout) :: worst
    real(wp), parameter :: h = 1e-5_wp
    type(surface_point_t) :: p, up, um, vp, vm
    type(status_t) :: st
    call slide%evaluate(u, v, 3, p, st)
    call slide%evaluate(u + h, v, 3, up, st)
    call slide%evaluate(u - h, v, 3, um, st)
    call slide%evaluate(u, v + h, 3, vp, st)
    call slide%evaluate(u, v - h, 3, vm, st)
    worst = max(worst, rel(p%ru, (up%r - um%r)/(2*h)), rel(p%ruu, (up%ru - um%ru)/(2*h)), &
                rel(p%ruuu, (up%ruu - um%ruu)/(2*h)), rel(p%ruv, (up%rv - um%rv)/(2*h)), &
                rel(p%ruuv, (up%ruv - um%ruv)/(2*h)), rel(p%ruvv, (up%rvv - um%rvv)/(2*h)), &
                rel(p%rv, (vp%r - vm%r)/(2*h)), rel(p%rvv, (vp%rv - vm%rv)/(2*h)), &
                rel(p%rvvv, (vp%rvv - vm%rvv)/(2*h)))
  end subroutine fd_errors

  !> What cannot be a patch is refused, saying why.
  subroutine patch_refusals()
    type(slide_description_t) :: d
    d = patch_slide(.true., 'patch', 1.0_wp)
    d%elements%patches(1)%offset(1, 4) = 0.01_wp
    call refused(d, 'the offset at station 0 m, angle 90 deg is 0.01 m: on the border of the grid')
    d = patch_slide(.true., 'patch', 1.0_wp)
    d%elements%patches(1)%offset(6, 4) = -0.7_wp
    call refused(d, 'the wall would pass through the centerline')
    d = patch_slide(.true., 'patch', 1.0_wp)
    d%elements%patches(1)%station(11) = 10.5_wp
    call refused(d, 'they must lie on the element, in [0, 10] m')
    d = patch_slide(.true., 'patch', 1.0_wp)
    d%elements%patches(1)%angle_deg = d%elements%patches(1)%angle_deg(:5)
    d%elements%patches(1)%offset = d%elements%patches(1)%offset(:, :5)
    call refused(d, 'needs at least 6 of each')
    d = patch_slide(.true., 'patch', 1.0_wp)
    d%section%parts = [section_part_description_t(kind='ellipse')]
    call refused(d, 'one circle or flume section, not ellipse')
    d = patch_slide(.true., 'patch', 1.0_wp)
    d%section%parts = [section_part_description_t(kind='flume', radius=r_slide)]
    d%elements%patches(1)%angle_deg = d%elements%patches(1)%angle_deg + 40
    call refused(d, 'they must lie in [0, 180] deg around the section')
    d = patch_slide(.true., 'patch', 1.0_wp)
    deallocate (d%elements%patches)
    call refused(d, 'element 3 is a patch without its grid of offsets')
    d = patch_slide(.true., 'straight', 1.0_wp)
    d%elements%patches = [quartic_grid(3, 1.0_wp)]
    call refused(d, 'element 3 (straight) has 1 patch grids')
    ! the global check sees the patch: after a U-turn of 2 m radius a patch
    ! whose wall bulges 3.2 m out (its extent 3.7 m) reaches the straight
    ! before the turn, 4 m away (extent 0.5 m); without it the slide is fine
    d = patch_slide(.true., 'patch', 40.0_wp)
    d%elements%elements = [slide_element_t(kind='straight', length=10.0_wp), &
                           slide_element_t(kind='curve', radius=2.0_wp, angle_deg=180.0_wp), &
                           slide_element_t(kind='patch', length=patch_length)]
    d%section%parts = [section_part_description_t(kind='circle', radius=0.5_wp)]
    call refused(d, 'the tube passes through itself')
    d%elements%patches(1)%offset = 0
    call built(d, 'the U-turn with a flat patch passes the global check')
  end subroutine patch_refusals

  subroutine built(d, what)
    type(slide_description_t), intent(in) :: d
    character(len=*), intent(in) :: what
    type(tube_surface_t) :: slide
    type(status_t) :: st
    call build_slide(d, slide, st)
    call check(st%ok(), what//': '//st%text())
  end subroutine built

  subroutine refused(d, words)
    type(slide_description_t), intent(in) :: d
    character(len=*), intent(in) :: words
    type(tube_surface_t) :: slide
    type(status_t) :: st
    call build_slide(d, slide, st)
    call check(.not. st%ok() .and. index(st%text(), words) > 0, 'refused ('//words//'): '//st%text())
  end subroutine refused

  !> A frictionless point mass from the curve of inputs/parts/patch_slide.nml
  !> over the patch and beyond (exact chain: u = sigma; the patch is u in
  !> [22.47, 34.47]).
  subroutine patch_normal_force()
    character(len=*), parameter :: text = '&run scenario = ''point_mass'' /'//nl// &
      '&solver method = ''adams'', rtol = 1e-10, atol = 1e-10 /'//nl// &
      '&surface kind = ''slide'', geometry_file = ''inputs/parts/patch_slide.nml'' /'//nl// &
      '&point_mass u0 = 11, v0 = 1.5707963267948966, du0 = 5, dv0 = 0, friction = ''none'' /'
    type(point_mass_t), target :: model
    type(point_mass_state_t) :: state, before, after
    type(ode_integrator_t) :: integrator
    type(ode_options_t) :: options
    type(input_text_t) :: input
    type(solver_config_t) :: solver
    type(status_t) :: st
    real(wp), allocatable :: y0(:)
    real(wp) :: y(5), t, n_prev, jump, drift, energy0, worst_joint, ends(2)
    integer :: k
    logical :: at_root
    call input_from_text('<test>', text, input, st)
    if (st%ok()) call build_point_mass(input, solver, model, y0, st)
    call check(st%ok(), 'point mass on the patch slide built: '//st%text())
    if (.not. st%ok()) return
    options = solver%options
    call model%state(y0, state, st)
    call integrator%start(model, 0.0_wp, y0, options, st)
    jump = 0
    drift = 0
    worst_joint = 0
    energy0 = state%kinetic_energy + state%potential_energy
    n_prev = state%normal_force
    ends = [12 + 5*120*pi/180, 12 + 5*120*pi/180 + 12]
    do k = 1, 20000
      call integrator%advance(1e-3_wp*k, t, y, st, root_found=at_root)
      if (.not. st%ok() .or. at_root) exit
      call model%state(y, state, st)
      drift = max(drift, abs(state%kinetic_energy + state%potential_energy - energy0)/state%kinetic_energy)
      jump = max(jump, abs(state%normal_force - n_prev)/standard_gravity)
      n_prev = state%normal_force
      if (y(1) >= ends(2) + 2) exit
    end do
    call integrator%destroy()
    call check(st%ok() .and. .not. at_root .and. y(1) >= ends(2) + 2, 'the mass slid over the patch: '//st%text())
    print '(a, 2es10.3)', 'largest change of N between 1 ms records (g), energy change relative to the '// &
      'kinetic: ', jump, drift
    ! frictionless: the energy is kept to the integration's tolerances (rtol
    ! 1e-10 over ~1e4 steps); a patch with a kink at its border would change
    ! the speed there (r_u jumps under the mass's (u', v'))
    call check(drift <= 1e-7_wp, 'the frictionless mass keeps its energy over the patch: '//real_text(drift))
    ! the mass swings on the curve's exit and over the patch's bulges
    ! (omega ~ sqrt(g/r) ~ 4 1/s, N ~ 1-2 g): ~0.01 g per ms. Bound 0.05 g
    call check(jump <= 0.05_wp, 'no jump of the normal force over the patch: '//real_text(jump)//' g')
    ! at each end, with the velocity of the mass there
    do k = 1, 2
      y = [ends(k) - 1e-9_wp, 1.3_wp, 5.0_wp, 0.8_wp, y0(5)]
      call model%state(y, before, st)
      y(1) = ends(k) + 1e-9_wp
      call model%state(y, after, st)
      worst_joint = max(worst_joint, abs(after%normal_force - before%normal_force)/(model%mass*standard_gravity))
    end do
    print '(a, es10.3)', 'N 1e-9 m before and after the patch''s ends, largest difference (mg): ', worst_joint
    ! dN/du ~ m v^2 d(curvature)/du ~ 10 mg/m at most: 2e-8 mg over 2e-9 m
    call check(worst_joint <= 1e-7_wp, 'the normal force does not jump at the patch''s ends: '// &
               real_text(worst_joint))
  end subroutine patch_normal_force

  pure real(wp) function rel(a, b)
    real(wp), intent(in) :: a(3), b(3)
    rel = norm2(a - b)/max(norm2(a), norm2(b), 1.0_wp)
  end function rel

  pure function unit(x) result(e)
    real(wp), intent(in) :: x(3)
    real(wp) :: e(3)
    e = x/norm2(x)
  end function unit

  !> The section of the quartic patch (angles 30..150 deg, windows' ramps
  !> 30-50 and 130-150 deg, stations 0-1 and 9-10 m) on a grid of u over
  !> the whole slide and v around it: the partials asked to order k are
  !> those asked to order 3, bit for bit, i + j <= k.
  subroutine patch_orders_agree()
    type(tube_surface_t) :: slide
    type(section_point_t) :: p(0:3)
    type(status_t) :: st
    real(wp) :: u0, u1, v0, v1, u, v
    integer :: i, j, k, m, n, mismatches, on_patch, on_ramp
    call build_slide(patch_slide(.true., 'patch', 1.0_wp), slide, st)
    call check(st%ok(), 'slide with the quartic patch built: '//st%text())
    if (.not. st%ok()) return
    call slide%domain(u0, u1, v0, v1)
    mismatches = 0; on_patch = 0; on_ramp = 0
    do i = 0, 400
      u = u0 + (u1 - u0)*i/400
      do j = 0, 144
        v = 2*pi*j/144 + 0.001_wp
        do k = 0, 3
          call slide%section%evaluate(u, v, k, p(k), st)
          call check(st%ok(), 'the patch''s section evaluated: '//st%text())
        end do
        do k = 0, 2
          do m = 0, k
            do n = 0, k - m
              if (any(p(k)%s(:, m, n) /= p(3)%s(:, m, n))) mismatches = mismatches + 1
            end do
          end do
        end do
        if (any(p(3)%s(:, 1, 0) /= 0)) then
          on_patch = on_patch + 1
          if (any(abs(v*180/pi - [40.0_wp, 140.0_wp]) < 10)) on_ramp = on_ramp + 1
        end if
      end do
    end do
    print '(a, i0, a, i0, a)', '  orders agree: ', on_patch, ' points on the patch, ', on_ramp, ' on a ramp in v'
    call check(on_patch > 1000 .and. on_ramp > 100, 'the grid covers the patch and its windows'' ramps')
    call check(mismatches == 0, 'the patch''s partials are the same bits at every order asked ('// &
               real_text(real(mismatches, wp))//' differ)')
  end subroutine patch_orders_agree

  !> The quartic patch's section over its circle against the same patches
  !> over plain_circle_t (the general path), on a grid of u over the whole
  !> slide and v around it: every partial at every order 0..3, and the
  !> extent at every u, the same bits.
  subroutine patch_circle_shortcuts()
    type(tube_surface_t) :: slide
    type(patch_section_t) :: general
    type(section_point_t) :: p, q
    type(status_t) :: st, st_general
    real(wp) :: u0, u1, v0, v1, u, v
    integer :: i, j, k, mismatches, extent_mismatches, on_patch, extents_on_patch
    call build_slide(patch_slide(.true., 'patch', 1.0_wp), slide, st)
    call check(st%ok(), 'slide with the quartic patch built: '//st%text())
    if (.not. st%ok()) return
    select type (patched => slide%section)
    type is (patch_section_t)
      general = new_patch_section(plain_circle_t(circle=circle_section_t(radius=r_slide)), patched%patches)
      call check(allocated(patched%base_samples) .and. .not. allocated(general%base_samples), &
                 'the circle''s points kept for the extent, the plain circle''s not')
      call slide%domain(u0, u1, v0, v1)
      mismatches = 0; extent_mismatches = 0; on_patch = 0; extents_on_patch = 0
      do i = 0, 400
        u = u0 + (u1 - u0)*i/400
        if (patched%extent(u) /= general%extent(u)) extent_mismatches = extent_mismatches + 1
        if (patched%extent(u) > r_slide) extents_on_patch = extents_on_patch + 1
        do j = 0, 144
          v = 2*pi*j/144 + 0.001_wp
          do k = 0, 3
            call patched%evaluate(u, v, k, p, st)
            call general%evaluate(u, v, k, q, st_general)
            if (.not. (st%ok() .and. st_general%ok()) .or. p%order /= q%order .or. any(p%s /= q%s)) &
              mismatches = mismatches + 1
          end do
          if (any(p%s(:, 1, 0) /= 0)) on_patch = on_patch + 1
        end do
      end do
      print '(a, i0, a, i0, a)', '  circle shortcuts: ', on_patch, ' points and ', extents_on_patch, &
        ' extents on the patch'
      call check(on_patch > 1000 .and. extents_on_patch > 50, 'the grid covers the patch')
      call check(mismatches == 0, 'the patch over its circle is the general path''s, bit for bit ('// &
                 real_text(real(mismatches, wp))//' differ)')
      call check(extent_mismatches == 0, 'the patch''s extent from the kept points is the general one, bit '// &
                 'for bit ('//real_text(real(extent_mismatches, wp))//' differ)')
    class default
      call check(.false., 'the slide''s section is a patch section')
    end select
  end subroutine patch_circle_shortcuts

  function real_text(x) result(text)
    real(wp), intent(in) :: x
    character(len=:), allocatable :: text
    character(len=32) :: buf
    write (buf, '(es23.16)') x
    text = trim(adjustl(buf))
  end function real_text
end program test_slide_patch
