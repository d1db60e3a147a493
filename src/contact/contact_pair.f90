!> Point contact between two surfaces on two moving bodies at position level
!> (thesis 3.5.3, A.3 of METHOD-PART2.md): one description, "body A surface S1
!> touches body B surface S2", expands into the elements, coordinates and the
!> closed loop of the thesis.
!>
!> Body B is carried by body A through a regular relative chain:
!>     K_A --S12(u12, v12)--> K_12 --prismatic z12 along z_12--> K_lift
!>         --free rotation (a1, a2, a3)--> K_B
!> S12 has the geometry and side of S1 ("where over surface 1 body B is"); the
!> free rotation (kinetostatics_free_rotation) has its first axis along the
!> normal z_12, so the spin about the normal is its unbounded first angle and
!> the chart changes only when B tilts by more than chart_limit from the pose
!> the chart was centred on. The contact frames are the Darboux frames
!>     K_1D = S1(u1, v1) on K_A,   K_2D = S2(u2, v2) on K_B,
!> and the loop closes them with the five conditions (3.86):
!>     g1..g3 = x_1D, y_1D, z_1D . (r_2D - r_1D) = 0   (plane-point)
!>     g4, g5 = z_1D . x_2D, z_1D . y_2D = 0            (plane-plane).
!> Independent coordinates q = (u12, v12, a1, a2, a3); dependent
!> beta = (u1, v1, u2, v2, z12). This partition is regular wherever the
!> surfaces touch with a finite relative curvature: z12 moves the contact along
!> the common normal, (u1, v1) and (u2, v2) along the two tangent planes.
!>
!> Sides: `side_1`, `side_2` (+1 or -1) orient each surface's normal (the
!> surface joint's sigma, (3.38)) towards the other body, i.e. out of the body's
!> material. The physical branch has antiparallel normals, z_1D . z_2D = -1;
!> g4, g5 alone also admit parallel normals, so the branch is checked
!> (`check_contact_branch`) after every closure that could have jumped.
!>
!> The open chain (`add_open_contact_pair`, for contacts without rolling):
!>     K_A --S1(u1, v1)--> K_1D --turn phi about z_1D--> K_T
!>         --inverse S2(u2, v2), K_2D = K_T Rx(pi)--> K_B
!> K_2D is S2's Darboux frame at (u2, v2) turned over (z_2D = -z_1D, x_2D at
!> the angle phi from x_1D), and the inverse surface joint
!> (kinetostatics_inverse_surface_joint) places K_B so that S2's frame there is
!> K_2D: the surfaces touch with antiparallel normals by construction, the
!> physical branch. Coordinates q = (u1, v1, phi, u2, v2), none dependent, no
!> closure; a closure monitor (contact_closure_monitor, record-only: evaluated
!> for records, not in the right-hand side) measures g1..g5 between K_1D and
!> S2's frame on body B's pose. Charts: (u1, v1),
!> (u2, v2) are the parameters of a chart of each surface, phi is unbounded.
!> Near a pole of a surface with charts (an ellipsoid's) S1 changes chart
!> and phi takes back its Darboux frame's turn (kinetostatics_surface_joint,
!> "Charts"), the inverse S2 likewise; in the loop S12 changes chart and the
!> free rotation's first angle (about S12's normal) takes the turn, while S1
!> and S2, whose (u, v) are dependent, change chart without a turn (the
!> closure and the no-slip condition do not see their frames' turn).
module contact_pair
  use base_kinds, only: wp
  use base_text, only: format_short
  use base_vector, only: cross
  use base_status, only: status_t, set_status, prefix_status, STATUS_INVALID_INPUT, STATUS_DOMAIN
  use geometry_surface, only: surface_t, surface_point_t
  use geometry_darboux, only: darboux_frame_t, darboux_frame
  use kinetostatics_joints, only: new_prismatic, new_revolute
  use kinetostatics_state, only: surface_chart_t
  use kinetostatics_surface_joint, only: new_surface_joint
  use kinetostatics_inverse_surface_joint, only: new_inverse_surface_joint
  use kinetostatics_plane_joint, only: new_plane_joint
  use kinetostatics_free_rotation, only: new_free_rotation
  use kinetostatics_measurements, only: new_measurement, MEASURE_PLANE_POINT, MEASURE_PLANE_PLANE
  use kinetostatics_mechanism, only: mechanism_t, mechanism_workspace_t
  use contact_surface_search, only: nearest_point, support_point
  use contact_closure_monitor, only: new_closure_monitor
  implicit none (type, external)
  private
  public :: contact_pair_t, add_contact_pair, add_loop_contact_pair, add_open_contact_pair, place_contact_pair, &
    place_open_contact_pair
  public :: check_contact_branch, starts_in_other_chart

  !> What one contact expanded into: indices into the mechanism's frames,
  !> scalars and elements.
  type :: contact_pair_t
    character(len=:), allocatable :: name
    integer :: frame_a = 0, frame_b = 0                   ! the two bodies
    integer :: frame_12 = 0, frame_lift = 0, frame_1d = 0, frame_2d = 0
    integer :: u12 = 0, v12 = 0, z12 = 0, angles(3) = 0  ! relative chain
    integer :: extra = 0   ! a second contact's loop (add_loop_contact_pair): its dependent of the carrying chain
    integer :: u1 = 0, v1 = 0, u2 = 0, v2 = 0            ! contact points
    integer :: gaps(5) = 0                               ! closure measurements g1..g5
    integer :: element_s1 = 0, element_s2 = 0, element_s12 = 0, element_rotation = 0
    real(wp) :: side_1 = 1, side_2 = 1
    ! the open chain (module comment): K_1D -> turn phi -> K_T -> inverse S2 -> K_B
    logical :: open = .false.
    integer :: phi = 0, frame_turn = 0
    integer :: chart = 0   ! the scalar of S2's chart (an ellipsoid's pole axis: 1, 2, 3 = B's x, y, z)
  contains
    procedure :: coordinates => pair_coordinates
    procedure :: dependents => pair_dependents
  end type contact_pair_t

contains

  !> Independent coordinates of the pair: u12, v12 and the three angles
  !> (open chain: u1, v1, phi, u2, v2).
  pure function pair_coordinates(self) result(q)
    class(contact_pair_t), intent(in) :: self
    integer :: q(5)
    if (self%open) then
      q = [self%u1, self%v1, self%phi, self%u2, self%v2]
    else
      q = [self%u12, self%v12, self%angles]
    end if
  end function pair_coordinates

  !> Dependent coordinates of its loop: u1, v1, u2, v2, z12 (a second
  !> contact's loop: extra for z12).
  pure function pair_dependents(self) result(beta)
    class(contact_pair_t), intent(in) :: self
    integer :: beta(5)
    beta = [self%u1, self%v1, self%u2, self%v2, self%z12]
    if (self%extra > 0) beta(5) = self%extra
  end function pair_dependents

  !> Adds the contact `name` between surface_1 on the body frame `frame_a` and
  !> surface_2 on body B, whose frame (named `body_b`) the chain creates. The
  !> caller adds B's mass and everything carried by B afterwards, and lists
  !> pair%coordinates() among the mechanism's coordinates.
  subroutine add_contact_pair(m, name, frame_a, surface_1, side_1, body_b, surface_2, side_2, pair, status)
    type(mechanism_t), intent(inout) :: m
    character(len=*), intent(in) :: name, body_b
    integer, intent(in) :: frame_a
    class(surface_t), intent(in) :: surface_1, surface_2
    real(wp), intent(in) :: side_1, side_2
    type(contact_pair_t), intent(out) :: pair
    type(status_t), intent(inout) :: status
    real(wp), parameter :: ez(3) = [0, 0, 1]
    real(wp), parameter :: identity(3, 3) = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 3])
    integer :: k
    character(len=2) :: digit
    call begin_pair(name, frame_a, side_1, side_2, pair, status)
    if (.not. status%ok()) return
    ! relative chain: S12, lift along its normal, free rotation
    pair%frame_12 = m%add_frame(name//'.12')
    pair%u12 = m%add_scalar(name//'.u12')
    pair%v12 = m%add_scalar(name//'.v12')
    call m%add_element(new_surface_joint(name//'.s12', frame_a, pair%frame_12, pair%u12, pair%v12, surface_1, &
                                         side_1, 1.0_wp, 0.0_wp, charts=.true.))
    pair%element_s12 = m%n_elements
    pair%frame_lift = m%add_frame(name//'.lift')
    pair%z12 = m%add_scalar(name//'.z12')
    call m%add_element(new_prismatic(name//'.lift', pair%frame_12, pair%frame_lift, pair%z12, ez))
    pair%frame_b = m%add_frame(body_b)
    do k = 1, 3
      write (digit, '(i1)') k
      pair%angles(k) = m%add_scalar(name//'.a'//trim(digit))
    end do
    call m%add_element(new_free_rotation(name//'.turn', pair%frame_lift, pair%frame_b, pair%angles, ez, identity))
    pair%element_rotation = m%n_elements
    ! the turn after S12 when it changes chart (kinetostatics_surface_joint, "Charts"): its first axis is S12's normal
    call m%elements(pair%element_s12)%e%set_chart_turn(pair%angles(1))
    ! the two contact frames
    call add_contact_frame_1(m, surface_1, pair, status)
    call add_contact_frame_2(m, surface_2, pair)
    call add_closure(m, pair, status)
  end subroutine add_contact_pair

  !> A second contact of a body the mechanism carries already (its frame
  !> `frame_b`): a closure loop, not a chain. The contact frames K_1D =
  !> S1(u1, v1) on frame_a and K_2D = S2(u2, v2) on frame_b, closed by the
  !> five conditions (3.86) as in add_contact_pair, with the dependent
  !> coordinates (u1, v1, u2, v2, extra): `extra` a coordinate of the
  !> chain that carries the body (the one that moves this contact most along
  !> its normal: contact_model). N is the cut force of g3, as in the loop.
  subroutine add_loop_contact_pair(m, name, frame_a, surface_1, side_1, frame_b, surface_2, side_2, extra, pair, &
                                   status)
    type(mechanism_t), intent(inout) :: m
    character(len=*), intent(in) :: name
    integer, intent(in) :: frame_a, frame_b, extra
    class(surface_t), intent(in) :: surface_1, surface_2
    real(wp), intent(in) :: side_1, side_2
    type(contact_pair_t), intent(out) :: pair
    type(status_t), intent(inout) :: status
    call begin_pair(name, frame_a, side_1, side_2, pair, status)
    if (.not. status%ok()) return
    pair%frame_b = frame_b
    call add_contact_frame_1(m, surface_1, pair, status)
    call add_contact_frame_2(m, surface_2, pair)
    pair%extra = extra
    call add_closure(m, pair, status)
  end subroutine add_loop_contact_pair

  !> The closure (3.86) of the pair's contact frames K_1D and K_2D: g1..g5
  !> measured, a loop of them on pair%dependents() (its branch: the normals
  !> against each other).
  subroutine add_closure(m, pair, status)
    type(mechanism_t), intent(inout) :: m
    type(contact_pair_t), intent(inout) :: pair
    type(status_t), intent(inout) :: status
    real(wp), parameter :: ex(3) = [1, 0, 0], ey(3) = [0, 1, 0], ez(3) = [0, 0, 1]
    associate (name => pair%name)
      call add_gap_scalars(m, pair)
      call m%add_element(new_measurement(name//'.g1', MEASURE_PLANE_POINT, pair%frame_1d, pair%frame_2d, &
                                         pair%gaps(1), axis_i=ex))
      call m%add_element(new_measurement(name//'.g2', MEASURE_PLANE_POINT, pair%frame_1d, pair%frame_2d, &
                                         pair%gaps(2), axis_i=ey))
      call m%add_element(new_measurement(name//'.g3', MEASURE_PLANE_POINT, pair%frame_1d, pair%frame_2d, &
                                         pair%gaps(3), axis_i=ez))
      call m%add_element(new_measurement(name//'.g4', MEASURE_PLANE_PLANE, pair%frame_1d, pair%frame_2d, &
                                         pair%gaps(4), axis_i=ez, axis_j=ex))
      call m%add_element(new_measurement(name//'.g5', MEASURE_PLANE_PLANE, pair%frame_1d, pair%frame_2d, &
                                         pair%gaps(5), axis_i=ez, axis_j=ey))
      call m%add_loop(name, pair%gaps, [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp], pair%dependents(), status)
      call m%set_loop_branch(name, pair%frame_1d, pair%frame_2d, status)
    end associate
  end subroutine add_closure

  !> The open chain of the contact `name` (module comment): S1 on the body
  !> frame `frame_a`, the turn phi about its normal and body B (frame named
  !> `body_b`) from S2 by the inverse surface joint; g1..g5 by a closure
  !> monitor. The caller adds B's mass and everything carried by B afterwards,
  !> lists pair%coordinates() among the mechanism's coordinates and sets the
  !> start with place_open_contact_pair.
  subroutine add_open_contact_pair(m, name, frame_a, surface_1, side_1, body_b, surface_2, side_2, pair, status)
    type(mechanism_t), intent(inout) :: m
    character(len=*), intent(in) :: name, body_b
    integer, intent(in) :: frame_a
    class(surface_t), intent(in) :: surface_1, surface_2
    real(wp), intent(in) :: side_1, side_2
    type(contact_pair_t), intent(out) :: pair
    type(status_t), intent(inout) :: status
    real(wp), parameter :: ez(3) = [0, 0, 1]
    real(wp), parameter :: turn_over(3, 3) = reshape([1, 0, 0, 0, -1, 0, 0, 0, -1], [3, 3])   ! Rx(pi)
    call begin_pair(name, frame_a, side_1, side_2, pair, status)
    if (.not. status%ok()) return
    pair%open = .true.
    call add_contact_frame_1(m, surface_1, pair, status)
    if (.not. status%ok()) return
    pair%frame_turn = m%add_frame(name//'.turn')
    pair%phi = m%add_scalar(name//'.phi')
    call m%add_element(new_revolute(name//'.turn', pair%frame_1d, pair%frame_turn, pair%phi, ez))
    call m%elements(pair%element_s1)%e%set_chart_turn(pair%phi)   ! takes S1's chart changes
    pair%frame_b = m%add_frame(body_b)
    pair%u2 = m%add_scalar(name//'.u2')
    pair%v2 = m%add_scalar(name//'.v2')
    pair%chart = m%add_scalar(name//'.chart', 3.0_wp)   ! an ellipsoid's pole axis (B's z: its own chart)
    call m%add_element(new_inverse_surface_joint(name//'.s2', pair%frame_turn, pair%frame_b, pair%u2, pair%v2, &
                                                 surface_2, side_2, 1.0_wp, 0.0_wp, turn_over, pair%phi, pair%chart))
    pair%element_s2 = m%n_elements
    call add_gap_scalars(m, pair)
    call m%add_element(new_closure_monitor(name//'.closure', pair%frame_1d, pair%frame_b, surface_2, side_2, &
                                           [pair%u2, pair%v2], pair%gaps, pair%chart, own_chart=3))
  end subroutine add_open_contact_pair

  !> Checks the sides and sets what both chains share.
  subroutine begin_pair(name, frame_a, side_1, side_2, pair, status)
    character(len=*), intent(in) :: name
    integer, intent(in) :: frame_a
    real(wp), intent(in) :: side_1, side_2
    type(contact_pair_t), intent(inout) :: pair
    type(status_t), intent(inout) :: status
    if (.not. status%ok()) return
    if (abs(abs(side_1) - 1) > 0 .or. abs(abs(side_2) - 1) > 0) then
      call set_status(status, STATUS_INVALID_INPUT, 'contact '''//name//''': the sides of its surfaces '// &
                      'must be +1 or -1')
      return
    end if
    pair%name = name
    pair%side_1 = side_1
    pair%side_2 = side_2
    pair%frame_a = frame_a
  end subroutine begin_pair

  !> The contact frame K_1D = S1(u1, v1) on body A. In the open chain an
  !> affine surface's (a plane's: surface_t's `affine`) by the plane joint
  !> (the same frame without the general joint's Darboux-frame rates, which
  !> vanish on a plane); the loop keeps the general joint (its placement
  !> reads the joint's surface, its results stay as they were).
  subroutine add_contact_frame_1(m, surface_1, pair, status)
    type(mechanism_t), intent(inout) :: m
    class(surface_t), intent(in) :: surface_1
    type(contact_pair_t), intent(inout) :: pair
    type(status_t), intent(inout) :: status
    pair%frame_1d = m%add_frame(pair%name//'.1D')
    pair%u1 = m%add_scalar(pair%name//'.u1')
    pair%v1 = m%add_scalar(pair%name//'.v1')
    if (pair%open .and. surface_1%affine()) then
      call m%add_element(new_plane_joint(pair%name//'.s1', pair%frame_a, pair%frame_1d, pair%u1, pair%v1, &
                                         surface_1, pair%side_1, 1.0_wp, 0.0_wp, status))
      pair%element_s1 = m%n_elements
      return
    end if
    call m%add_element(new_surface_joint(pair%name//'.s1', pair%frame_a, pair%frame_1d, pair%u1, pair%v1, &
                                         surface_1, pair%side_1, 1.0_wp, 0.0_wp, charts=.true.))
    pair%element_s1 = m%n_elements
  end subroutine add_contact_frame_1

  !> The contact frame K_2D = S2(u2, v2) on the body's frame_b (a surface
  !> joint with charts), of add_contact_pair and add_loop_contact_pair alike.
  subroutine add_contact_frame_2(m, surface_2, pair)
    type(mechanism_t), intent(inout) :: m
    class(surface_t), intent(in) :: surface_2
    type(contact_pair_t), intent(inout) :: pair
    pair%frame_2d = m%add_frame(pair%name//'.2D')
    pair%u2 = m%add_scalar(pair%name//'.u2')
    pair%v2 = m%add_scalar(pair%name//'.v2')
    call m%add_element(new_surface_joint(pair%name//'.s2', pair%frame_b, pair%frame_2d, pair%u2, pair%v2, &
                                         surface_2, pair%side_2, 1.0_wp, 0.0_wp, charts=.true.))
    pair%element_s2 = m%n_elements
  end subroutine add_contact_frame_2

  !> The scalars of the closure functions g1..g5.
  subroutine add_gap_scalars(m, pair)
    type(mechanism_t), intent(inout) :: m
    type(contact_pair_t), intent(inout) :: pair
    integer :: k
    character(len=2) :: digit
    do k = 1, 5
      write (digit, '(i1)') k
      pair%gaps(k) = m%add_scalar(pair%name//'.g'//trim(digit))
    end do
  end subroutine add_gap_scalars

  !> Start values of an open pair from the closed configuration of a loop
  !> pair (`closed`, whose mechanism's state is `mc`): the same contact
  !> points, and phi the angle from x_1D to x_2D about z_1D.
  subroutine place_open_contact_pair(m, pair, mc, closed)
    type(mechanism_t), intent(inout) :: m
    type(contact_pair_t), intent(in) :: pair, closed
    type(mechanism_workspace_t), intent(in) :: mc
    real(wp) :: x2(3)
    type(surface_chart_t) :: chart
    m%scalars(pair%u1)%q = mc%scalars(closed%u1)%q
    m%scalars(pair%v1)%q = mc%scalars(closed%v1)%q
    m%scalars(pair%u2)%q = mc%scalars(closed%u2)%q
    m%scalars(pair%v2)%q = mc%scalars(closed%v2)%q
    x2 = mc%frames(closed%frame_2d)%rot(:, 1)
    m%scalars(pair%phi)%q = atan2(dot_product(x2, mc%frames(closed%frame_1d)%rot(:, 2)), &
                                  dot_product(x2, mc%frames(closed%frame_1d)%rot(:, 1)))
    ! the charts the loop started in (place_contact_pair), if it changed any
    associate (loop_s1 => mc%elements(closed%element_s1)%e)
      if (loop_s1%chart_changes() > 0) then
        call loop_s1%surface_chart(chart)
        call m%elements(pair%element_s1)%e%take_surface_chart(chart, loop_s1%chart_changes())
      end if
    end associate
    associate (loop_s2 => mc%elements(closed%element_s2)%e)
      if (loop_s2%chart_changes() > 0) then
        call loop_s2%surface_chart(chart)
        call m%elements(pair%element_s2)%e%take_surface_chart(chart, loop_s2%chart_changes())
        m%scalars(pair%chart)%q = chart%index
      end if
    end associate
  end subroutine place_open_contact_pair

  !> Start values of the pair from the poses of A and B (world rotation and
  !> origin of each): the chain sits over the point of S1 nearest to B's
  !> origin, its rotation chart is centred on B's orientation (angles zero),
  !> and the contact points start at that point of S1 and at the support point
  !> of S2 against S1's normal there; z12 then puts that support point onto
  !> the tangent plane, i.e. moves B along the normal by `gap` (m, positive:
  !> B was above the surface; `normal`: that normal, world axes). The loop is
  !> closed afterwards by the mechanism (set_positions / check_start), which
  !> makes the contact exact.
  subroutine place_contact_pair(m, pair, rot_a, r_a, rot_b, r_b, gap, normal, status)
    type(mechanism_t), intent(inout) :: m
    type(contact_pair_t), intent(in) :: pair
    real(wp), intent(in) :: rot_a(3, 3), r_a(3), rot_b(3, 3), r_b(3)
    real(wp), intent(out) :: gap, normal(3)
    type(status_t), intent(inout) :: status
    real(wp) :: p(3), rel(3, 3), n_b(3), u12, v12, u2, v2, c_b(3)
    type(surface_point_t) :: pt1, pt2
    type(darboux_frame_t) :: d12
    type(surface_chart_t) :: chart_1, chart_2
    gap = 0
    normal = 0
    if (.not. status%ok()) return
    call m%elements(pair%element_s1)%e%surface_chart(chart_1)
    call m%elements(pair%element_s2)%e%surface_chart(chart_2)
    associate (s1 => chart_1%surface, s2 => chart_2%surface)
      p = matmul(transpose(rot_a), r_b - r_a)                ! B's origin in A's coordinates
      call nearest_point(s1, p, u12, v12, status)
      if (status%ok()) call s1%evaluate(u12, v12, 3, pt1, status)
      if (status%ok()) call darboux_frame(pt1, pair%side_1, 1.0_wp, 0.0_wp, d12, status)
      if (.not. status%ok()) then
        call prefix_status(status, 'contact '''//pair%name//''': placing body B over surface 1')
        return
      end if
      rel = matmul(transpose(d12%r), matmul(transpose(rot_a), rot_b))   ! B relative to K_12
      n_b = matmul(transpose(rel), [0.0_wp, 0.0_wp, 1.0_wp])           ! S1's normal in B's coordinates
      call support_point(s2, n_b, u2, v2, status)
      if (status%ok()) call s2%evaluate(u2, v2, 1, pt2, status)
      if (.not. status%ok()) then
        call prefix_status(status, 'contact '''//pair%name//''': finding where body B touches')
        return
      end if
      call check_sides(pair, pt2, n_b, status)
      if (.not. status%ok()) return
      c_b = matmul(rel, pt2%r)                                ! support point relative to B's origin, K_12 axes
      gap = dot_product(p - pt1%r, d12%r(:, 3)) + c_b(3)
      normal = matmul(rot_a, d12%r(:, 3))
    end associate
    m%scalars(pair%u12)%q = u12
    m%scalars(pair%v12)%q = v12
    m%scalars(pair%angles)%q = 0
    m%scalars(pair%u1)%q = u12
    m%scalars(pair%v1)%q = v12
    m%scalars(pair%u2)%q = u2
    m%scalars(pair%v2)%q = v2
    m%scalars(pair%z12)%q = -c_b(3)
    call m%elements(pair%element_rotation)%e%centre_chart(rel)
    ! a contact that starts at (or within the margin of) a pole of a surface
    ! with charts: its surface joints change chart before the loop is closed
    ! (at rest), the turn after each taking its Darboux frame's turn
    call m%elements(pair%element_s12)%e%start_chart(m%scalars)
    call m%elements(pair%element_s1)%e%start_chart(m%scalars)
    call m%elements(pair%element_s2)%e%start_chart(m%scalars)
  end subroutine place_contact_pair

  !> Whether a surface joint of the loop pair changed chart at its placement
  !> (place_contact_pair): its (u, v) are then not the surface's own parameters.
  logical function starts_in_other_chart(m, pair) result(other)
    type(mechanism_workspace_t), intent(in) :: m
    type(contact_pair_t), intent(in) :: pair
    integer :: k, joints(3)
    other = .false.
    joints = [pair%element_s12, pair%element_s1, pair%element_s2]
    do k = 1, 3
      other = other .or. m%elements(joints(k))%e%chart_changes() > 0
    end do
  end function starts_in_other_chart

  !> At the placement, before any closure: S2's normal (side_2) at its support
  !> point against S1's normal n_b (side_1, in B's coordinates) is -n_b on
  !> the physical branch and +n_b if a side is wrong; a wrong side would close
  !> the loop on the parallel branch (g4, g5 hold there too), whose message
  !> could only say so in coordinates. The support point was sought on S1's
  !> side as side_1 has it, so side_2 is the likelier culprit (a wrong side_1
  !> puts B into body 1: the contact does not press at the start). At a
  !> singular point of S2's parametrisation (a pole) the normal is not
  !> known here: the check after the closure (check_contact_branch) remains.
  subroutine check_sides(pair, pt2, n_b, status)
    type(contact_pair_t), intent(in) :: pair
    type(surface_point_t), intent(in) :: pt2
    real(wp), intent(in) :: n_b(3)
    type(status_t), intent(inout) :: status
    real(wp) :: w(3), c
    w = cross(pt2%ru, pt2%rv)
    if (.not. norm2(w) > 1e-8_wp*(dot_product(pt2%ru, pt2%ru) + dot_product(pt2%rv, pt2%rv))) return
    c = pair%side_2*dot_product(w, n_b)/norm2(w)
    if (c > 0) call set_status(status, STATUS_INVALID_INPUT, 'contact '''//pair%name//''': side_1 = '// &
      side_text(pair%side_1)//' and side_2 = '//side_text(pair%side_2)//' point the normals of shape_1 and '// &
      'shape_2 the same way where they touch (parallel normals, n_1 . n_2 = '//format_short(c)//'); at a '// &
      'contact they are opposite, each out of its body towards the other: flip side_2 (side_2 = '// &
      side_text(-pair%side_2)//'), or side_1 if it is shape_1''s normal that points into its body')
  end subroutine check_sides

  pure function side_text(side) result(text)
    real(wp), intent(in) :: side
    character(len=2) :: text
    text = merge('+1', '-1', side > 0)
  end function side_text

  !> After a closure: the normals must be antiparallel (z_1D . z_2D < 0).
  subroutine check_contact_branch(m, pair, status)
    type(mechanism_workspace_t), intent(in) :: m
    type(contact_pair_t), intent(in) :: pair
    type(status_t), intent(inout) :: status
    real(wp) :: c
    if (.not. status%ok()) return
    c = dot_product(m%frames(pair%frame_1d)%rot(:, 3), m%frames(pair%frame_2d)%rot(:, 3))
    if (c > 0) call set_status(status, STATUS_DOMAIN, 'contact '''//pair%name//''' closed with parallel '// &
      'normals (z_1D . z_2D = '//format_short(c)//'), the non-physical branch of (3.86): the normals of '// &
      'shape_1 and shape_2 point the same way; flip side_1 or side_2 (each must point its surface''s '// &
      'normal out of its body towards the other body)')
  end subroutine check_contact_branch

end module contact_pair
