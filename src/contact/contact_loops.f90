!> A body on several closed contacts (issue 25): the first of its closed
!> contacts (in the description's order) carries it as a chain
!> (contact_pair), each further one is a closure loop on the body the chain
!> placed (contact_pair add_loop_contact_pair), as the sled's front contact
!> is. A point contact takes one degree of freedom, but its five conditions
!> (3.86) have four dependents of their own (u1, v1, u2, v2), so one
!> coordinate of the carrying chain becomes dependent too: the one whose
!> rate moves the contact's points apart along their normal the most, per
!> the size of the motion it makes there,
!>     |n . w_k| / (|w_k| + l |omega_k|),
!> w_k the velocity of the body's contact point relative to the other's
!> (the ground's: 0) per unit rate of coordinate k, omega_k the relative
!> angular velocity, l the distance from the body's origin to its contact
!> point: 1 for a coordinate that moves the point straight along the normal,
!> 0 for one that slides or spins it in the tangent plane. The gap's rate is
!> n . w (contact_gap gap_rate), so with the contact points free to move on
!> their surfaces (u1, v1, u2, v2) the closure's Jacobian is regular where
!> that coordinate's n . w_k is not 0. It is chosen at the phase's start,
!> from the mechanism without the loop (its contacts apart) at the start
!> pose; none above min_normal_share is refused (the contact's normal
!> depends on the others': a body on two contacts of one line, say).
!>
!> The loop's start: its points from the contact search at the start pose
!> (contact_gap start_from_search: the nearest point of shape_1 and the
!> support point of shape_2), in the surfaces' own parameters; the closure
!> closes the gap left there (the body moved along the normal by it).
module contact_loops
  use base_kinds, only: wp
  use base_text, only: format_short
  use base_vector, only: cross
  use base_status, only: status_t, set_status, prefix_status, STATUS_INVALID_INPUT
  use geometry_surface, only: surface_t
  use kinetostatics_mechanism, only: mechanism_t, mechanism_workspace_t
  use contact_gap, only: contact_gap_t, new_contact_gap
  use contact_system, only: contact_system_t, body_index, shape_index, LEVEL_POSITION
  implicit none (type, external)
  private
  public :: loop_start_t, start_loop_contact, second_contacts, start_loops, min_normal_share

  !> The smallest share of a coordinate's motion along the normal that may
  !> close a loop (module comment).
  real(wp), parameter :: min_normal_share = 1e-3_wp

  !> What a loop contact starts from: its points in the surfaces' own
  !> parameters, the gap there, and the carrying chain's coordinate it makes
  !> dependent (its scalar's name).
  type :: loop_start_t
    logical :: used = .false.
    real(wp) :: x(4) = 0                      ! u1, v1, u2, v2
    real(wp) :: gap = 0                       ! m, at the start pose (the closure closes it)
    real(wp) :: share = 0                     ! the chosen coordinate's |n . w| / (|w| + l |omega|)
    character(len=:), allocatable :: extra    ! the chosen coordinate's scalar name
  end type loop_start_t

contains

  !> The start of the loop contact `name` between surface_1 (side_1) on
  !> frame_a and surface_2 (side_2) on frame_b of the mechanism m, placed
  !> in `work` at its start (positions set) without that contact: its points
  !> from the contact search, and the coordinate of m to make dependent
  !> (module comment), none of `taken` (the scalars other loops took).
  subroutine start_loop_contact(m, work, name, frame_a, surface_1, side_1, frame_b, surface_2, side_2, taken, &
                                start, status)
    type(mechanism_t), intent(in) :: m
    type(mechanism_workspace_t), intent(inout) :: work
    character(len=*), intent(in) :: name
    integer, intent(in) :: frame_a, frame_b
    class(surface_t), intent(in) :: surface_1, surface_2
    real(wp), intent(in) :: side_1, side_2
    integer, intent(in) :: taken(:)
    type(loop_start_t), intent(out) :: start
    type(status_t), intent(inout) :: status
    type(contact_gap_t) :: gap
    real(wp) :: unit(m%ns), w(3), omega(3), share, arm, saved(m%ns)
    integer :: k, best
    if (.not. status%ok()) return
    gap = new_contact_gap(surface_1, side_1, surface_2, side_2, [0.0_wp, 0.0_wp, 0.0_wp, 0.0_wp])
    associate (a => work%frames(frame_a), b => work%frames(frame_b))
      call gap%start_from_search(a%rot, a%r, b%rot, b%r, status)
      if (status%ok()) call gap%parameters(start%x, status)
      if (.not. status%ok()) then
        call prefix_status(status, 'contact '''//name//''': where it touches at the start')
        return
      end if
      start%gap = gap%gap
      saved = work%scalars(m%q(m%speeds))%qd
      arm = norm2(gap%point_2 - b%r)
      best = 0
      start%share = 0
      do k = 1, m%ns
        if (any(taken == m%q(m%speeds(k)))) cycle
        unit = 0
        unit(k) = 1
        call m%set_velocities(work, unit)
        w = b%v + cross(b%omega, gap%point_2 - b%r) - a%v - cross(a%omega, gap%point_1 - a%r)
        omega = b%omega - a%omega
        if (.not. norm2(w) + arm*norm2(omega) > 0) cycle
        share = abs(dot_product(gap%normal, w))/(norm2(w) + arm*norm2(omega))
        if (share > start%share) then
          start%share = share
          best = k
        end if
      end do
      call m%set_velocities(work, saved)
    end associate
    if (.not. start%share > min_normal_share) then
      call set_status(status, STATUS_INVALID_INPUT, 'contact '''//name//''': no coordinate of the contact that '// &
        'carries its body moves it along its normal (the largest share '//format_short(start%share)//', at '// &
        'least '//format_short(min_normal_share)//' needed): its normal depends on the body''s other closed '// &
        'contacts'' (several closed contacts of one body must each take a degree of freedom of its own)')
      return
    end if
    start%used = .true.
    start%extra = trim(m%scalar_names(m%q(m%speeds(best))))
  end subroutine start_loop_contact
  !> Each closed contact whose body_2 an earlier closed contact carries
  !> already (a loop: contact_loops).
  pure function second_contacts(system) result(second)
    type(contact_system_t), intent(in) :: system
    logical :: second(size(system%contacts))
    integer :: k, j
    second = .false.
    do k = 1, size(system%contacts)
      if (system%contacts(k)%start_open) cycle
      second(k) = any([(.not. system%contacts(j)%start_open .and. system%contacts(j)%body_2 == &
                        system%contacts(k)%body_2, j = 1, k - 1)])
    end do
  end function second_contacts

  !> The start of each loop contact of `system` (second_contacts) from the
  !> mechanism m of the others at its start (work) (contact_loops
  !> start_loop_contact): refused at velocity level or rolling (the loop,
  !> and the body's carrying contact, at position level without rolling).
  subroutine start_loops(system, m, work, body_frame, loops, status)
    type(contact_system_t), intent(in) :: system
    type(mechanism_t), intent(in) :: m
    type(mechanism_workspace_t), intent(inout) :: work
    integer, intent(in) :: body_frame(:)   ! each body's frame in m (the ground first)
    type(loop_start_t), allocatable, intent(out) :: loops(:)
    type(status_t), intent(inout) :: status
    logical :: second(size(system%contacts))
    integer, allocatable :: taken(:)
    integer :: k, j, b1
    allocate (loops(size(system%contacts)), taken(0))
    if (.not. status%ok()) return
    second = second_contacts(system)
    do k = 1, size(system%contacts)
      if (.not. second(k)) cycle
      associate (c => system%contacts(k))
        j = findloc([(.not. system%contacts(j)%start_open .and. system%contacts(j)%body_2 == c%body_2, &
                      j = 1, size(system%contacts))], .true., dim=1)
        if (any([c%level, system%contacts(j)%level] /= LEVEL_POSITION) .or. c%rolling .or. &
            system%contacts(j)%rolling) then
          call set_status(status, STATUS_INVALID_INPUT, 'contact '''//c%name//''': a second closed contact of '// &
            'body '''//c%body_2//''' (with '''//system%contacts(j)%name//''') is a closure loop, built at '// &
            'position level without rolling, at both: give level = ''position'' and no rolling')
          return
        end if
        b1 = body_index(system, c%body_1)
        associate (s1 => system%shapes(shape_index(system, c%shape_1))%surface, &
                   s2 => system%shapes(shape_index(system, c%shape_2))%surface)
          call start_loop_contact(m, work, c%name, body_frame(b1 + 1), s1, c%side_1, &
                                  body_frame(body_index(system, c%body_2) + 1), s2, c%side_2, taken, &
                                  loops(k), status)
          if (.not. status%ok()) return
          taken = [taken, m%scalar_index(loops(k)%extra)]
        end associate
      end associate
    end do
  end subroutine start_loops
end module contact_loops
