!> The closure functions g1..g5 of a contact (3.86), measured for contacts
!> whose chain keeps them closed by construction (the open chain of
!> contact_pair): a check that does not trust the chain's way to body B.
!> K_1D = S1(u1, v1) on K_A is the chain's first link (the plane or surface
!> joint's output frame, read here: evaluating S1 again at the same (u1, v1)
!> on the same K_A would repeat that map). What the chain builds after it
!> (the turn and the inverse of S2) is checked from body B's pose alone: S2's
!> Darboux frame K_2D = S2(u2, v2) on K_B (a forward surface joint on a local
!> frame), and
!>     g1..g3 = x_1D, y_1D, z_1D . (r_2D - r_1D),   g4, g5 = z_1D . x_2D, z_1D . y_2D.
!> A monitor of positions only: nothing in the mechanism reads its outputs
!> (they are recorded, not closure measurements), so it is a record-only
!> element (element_t): the position passes of the dynamics skip it and the
!> mechanism evaluates it for a complete state (a record); its velocity and
!> acceleration maps leave their rates alone (zero) and its force map passes
!> nothing back. A record costs one surface point to first order, a
!> right-hand side nothing. The (u2, v2) of a surface with charts (an
!> ellipsoid) are those of the chart the inverse joint uses
!> (kinetostatics_inverse_surface_joint, "Charts"): the monitor reads the
!> chart from the scalar `chart` and measures with it.
module contact_closure_monitor
  use base_kinds, only: wp
  use base_status, only: status_t, prefix_status
  use geometry_surface, only: surface_t
  use kinetostatics_state, only: element_t, element_links_t, frame_state_t, scalar_state_t
  use kinetostatics_surface_joint, only: surface_joint_t, new_surface_joint
  implicit none (type, external)
  private
  public :: closure_monitor_t, new_closure_monitor

  type, extends(element_t) :: closure_monitor_t
    integer :: frame_1d = 0, frame_b = 0
    integer :: contact(2) = 0                   ! scalars u2, v2
    integer :: gaps(5) = 0                      ! output scalars g1..g5
    type(surface_joint_t) :: joint_2            ! S2 on K_B (local frames 1 -> 2)
    ! the surface's chart (module comment): the scalar's initial value names its own
    integer :: var_chart = 0, own_chart = 0, chart_in_use = 0
    class(surface_t), allocatable :: own_surface
    real(wp) :: chart(3, 3) = reshape([1, 0, 0, 0, 1, 0, 0, 0, 1], [3, 3])
  contains
    procedure :: position => monitor_position
    procedure :: velocity => monitor_motion
    procedure :: acceleration => monitor_motion
    procedure :: force => monitor_force
    procedure :: links => monitor_links
  end type closure_monitor_t

contains

  !> frame_1d: the contact frame K_1D on body A; surface_2 with side_2 on
  !> the body frame frame_b at the scalars contact = [u2, v2]; chart: the
  !> scalar of the chart of a surface with charts (module comment), whose
  !> value names the surface's own chart at the start, or own_chart does
  !> (a contact that starts in another chart).
  function new_closure_monitor(name, frame_1d, frame_b, surface_2, side_2, contact, gaps, chart, own_chart) &
      result(e)
    character(len=*), intent(in) :: name
    integer, intent(in) :: frame_1d, frame_b, contact(2), gaps(5)
    integer, intent(in), optional :: chart, own_chart
    class(surface_t), intent(in) :: surface_2
    real(wp), intent(in) :: side_2
    type(closure_monitor_t) :: e
    e%name = name
    e%record_only = .true.
    e%frame_1d = frame_1d
    e%frame_b = frame_b
    e%contact = contact
    e%gaps = gaps
    e%joint_2 = new_surface_joint(name//'.s2', 1, 2, 1, 2, surface_2, side_2, 1.0_wp, 0.0_wp)
    if (present(chart)) then
      if (surface_2%has_charts()) then
        allocate (e%own_surface, source=surface_2)
        e%var_chart = chart
        if (present(own_chart)) then
          e%own_chart = own_chart
          e%chart_in_use = own_chart
        end if
      end if
    end if
  end function new_closure_monitor

  pure subroutine monitor_position(self, frames, scalars, status)
    class(closure_monitor_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    type(status_t), intent(inout) :: status
    type(frame_state_t) :: two(2)
    type(scalar_state_t) :: uv(2)
    class(surface_t), allocatable :: chart_surface
    real(wp) :: g(5)
    integer :: k
    if (self%var_chart > 0) then
      if (self%own_chart == 0) then   ! the first state names the surface's own chart
        self%own_chart = nint(scalars(self%var_chart)%q)
        self%chart_in_use = self%own_chart
      end if
      if (nint(scalars(self%var_chart)%q) /= self%chart_in_use) then
        self%chart_in_use = nint(scalars(self%var_chart)%q)
        call self%own_surface%chart(self%chart_in_use, chart_surface, self%chart)
        self%joint_2%surface = chart_surface
      end if
    end if
    if (self%chart_in_use == self%own_chart) then
      two(1)%rot = frames(self%frame_b)%rot
    else
      two(1)%rot = matmul(frames(self%frame_b)%rot, self%chart)
    end if
    two(1)%r = frames(self%frame_b)%r
    uv = scalars(self%contact)
    call self%joint_2%position(two, uv, status)
    if (.not. status%ok()) then
      call prefix_status(status, 'closure monitor '''//self%name//'''')
      return
    end if
    associate (one => frames(self%frame_1d))
      g(1:3) = matmul(transpose(one%rot), two(2)%r - one%r)
      g(4) = dot_product(one%rot(:, 3), two(2)%rot(:, 1))
      g(5) = dot_product(one%rot(:, 3), two(2)%rot(:, 2))
    end associate
    do k = 1, 5
      scalars(self%gaps(k))%q = g(k)
    end do
  end subroutine monitor_position

  !> Rates are not computed (module comment).
  pure subroutine monitor_motion(self, frames, scalars)
    class(closure_monitor_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    associate (unused => self, unused_f => frames, unused_s => scalars)
    end associate
  end subroutine monitor_motion

  pure subroutine monitor_force(self, frames, scalars, inertia, applied)
    class(closure_monitor_t), intent(inout) :: self
    type(frame_state_t), intent(inout) :: frames(:)
    type(scalar_state_t), intent(inout) :: scalars(:)
    logical, intent(in) :: inertia, applied
    associate (unused => self, unused_f => frames, unused_s => scalars, unused_i => inertia, unused_a => applied)
    end associate
  end subroutine monitor_force

  pure subroutine monitor_links(self, links)
    class(closure_monitor_t), intent(in) :: self
    type(element_links_t), intent(out) :: links
    links = element_links_t(.true., [self%frame_1d, self%frame_b], self%contact, [integer ::], self%gaps, &
                            relative=.true.)
  end subroutine monitor_links
end module contact_closure_monitor
