!> A landing at one point of a mechanism (flight and landing, issue 25): the
!> signed gap of a point above a surface and its rate, and the impact there
!> with the effective mass of the whole mechanism at that point. Shared by
!> the body-slide rider's flights (rider_flight) and the vehicles' (&sled
!> may_fly, rider_vehicle_flight).
!>
!> The gap: the point frame's origin's distance from its foot frame's
!> origin along the foot frame's z (the surface's normal at the foot point,
!> positive on the mechanism's side), positions set; its rate the point's
!> velocity along that normal (the foot frame's velocity is tangent to the
!> surface), velocities set.
!>
!> The impact: the impulse L at the point comes from kinetostatics_impact's
!> law (restitution, Coulomb mu) with the Delassus matrix K = J M^-1 J^T of
!> the mechanism (J: the point's velocity per unit speed, M: the mass matrix
!> in the speeds, from the kinetic energy T(e_i) and T(e_i + e_j)), so the
!> effective mass is that of the whole mechanism at that point, whatever
!> else holds it; the speeds change by M^-1 J^T L, the positions not. A
!> rebound slower than close_speed closes the contact with a further
!> frictionless plastic impulse that stops its normal speed; its energy is
!> returned apart.
module kinetostatics_point_impact
  use base_kinds, only: wp
  use base_text, only: format_short
  use base_status, only: status_t, set_status, STATUS_DOMAIN
  use numerics_linear_algebra, only: lu_factor, lu_solve
  use kinetostatics_mechanism, only: mechanism_t, mechanism_workspace_t
  use kinetostatics_impact, only: impact_law_t, impact_outcome_t, resolve_impact
  implicit none (type, external)
  private
  public :: point_gap, point_gap_rate, point_impact, gap_root, speeds_mass

  !> m: how far a contact must open after its take-off before the landing
  !> is watched. At the lift-off the gap, its rate and its second derivative
  !> are zero and it grows as s^3; its values carry the integration's error
  !> of the positions (rtol 1e-10 of the slide's parameter u ~ 10..100 plus
  !> atol 1e-9: a few 1e-9 m; the rider's crest's gap went to -1.5e-9 m and
  !> back within 1e-4 s). So the landing is watched once the gap has opened
  !> by opening_gap, far above that noise; until then a landing is a sink by
  !> sink_gap (only a true return of the point reaches it).
  real(wp), parameter, public :: opening_gap = 1e-7_wp, sink_gap = 1e-6_wp

contains

  !> An open contact's root: until its gap has opened by opening_gap,
  !> (opening_gap - gap)(gap + sink_gap) (zero where it opens or sinks
  !> back), then the gap.
  pure real(wp) function gap_root(gap, opened) result(g)
    real(wp), intent(in) :: gap
    logical, intent(in) :: opened
    if (opened) then
      g = gap
    else
      g = (opening_gap - gap)*(gap + sink_gap)
    end if
  end function gap_root

  !> The signed gap of frame `point` above its foot frame `foot` (m).
  pure real(wp) function point_gap(work, point, foot) result(gap)
    type(mechanism_workspace_t), intent(in) :: work
    integer, intent(in) :: point, foot
    associate (p => work%frames(point), d => work%frames(foot))
      gap = dot_product(p%r - d%r, d%rot(:, 3))
    end associate
  end function point_gap

  !> Its rate (m/s): the point's velocity along the foot frame's normal.
  pure real(wp) function point_gap_rate(work, point, foot) result(rate)
    type(mechanism_workspace_t), intent(in) :: work
    integer, intent(in) :: point, foot
    associate (p => work%frames(point), d => work%frames(foot))
      rate = dot_product(p%v, d%rot(:, 3))   ! d%v is tangent to the surface
    end associate
  end function point_gap_rate

  !> The impact of frame `point` on the surface under its foot frame `foot`
  !> for m at state y = [q, s, ...]: the impulse of `law` and, for a rebound
  !> slower than close_speed (m/s), the closing one; s updated in y.
  !> `closed`: the contact closes; closing_impulse (N s, at the point) and
  !> closing_energy (J) the closing's. `name` names the contact in messages
  !> ("the <name>'s landing: ...").
  subroutine point_impact(m, work, point, foot, name, y, law, close_speed, outcome, closed, closing_impulse, &
                          closing_energy, status)
    type(mechanism_t), intent(in) :: m
    type(mechanism_workspace_t), intent(inout) :: work
    integer, intent(in) :: point, foot
    character(len=*), intent(in) :: name
    real(wp), intent(inout) :: y(:)
    type(impact_law_t), intent(in) :: law
    real(wp), intent(in) :: close_speed
    type(impact_outcome_t), intent(out) :: outcome
    logical, intent(out) :: closed
    real(wp), intent(out) :: closing_impulse(3), closing_energy
    type(status_t), intent(inout) :: status
    real(wp), allocatable :: jac(:, :), mass(:, :), minv_jt(:, :), e(:), s(:), lu(:, :)
    real(wp) :: k(3, 3), normal(3), v(3), vn
    integer, allocatable :: ipiv(:)
    integer :: i, n
    n = m%f
    allocate (jac(3, n), minv_jt(n, 3), e(n), s(n), lu(n, n), ipiv(n))
    closed = .false.
    closing_impulse = 0
    closing_energy = 0
    s = y(n + 1:2*n)
    call m%set_positions(work, y(1:n), status)
    if (.not. status%ok()) return
    ! J: the point's velocity per unit speed
    do i = 1, n
      e = 0
      e(i) = 1
      call m%set_velocities(work, e)
      jac(:, i) = work%frames(point)%v
    end do
    mass = speeds_mass(m, work)
    call m%set_velocities(work, s)
    v = work%frames(point)%v
    normal = work%frames(foot)%rot(:, 3)
    lu = mass
    call lu_factor(lu, ipiv, status)
    minv_jt = transpose(jac)
    if (status%ok()) call lu_solve(lu, ipiv, minv_jt, status)
    if (.not. status%ok()) then
      call set_status(status, STATUS_DOMAIN, 'the '//name//'''s landing: the mass matrix is singular there')
      return
    end if
    k = matmul(jac, minv_jt)
    k = (k + transpose(k))/2
    call resolve_impact(law, k, normal, v, outcome, status)
    if (.not. status%ok()) return
    if (.not. outcome%approaching) then
      ! the gap closed, so the point moved towards the surface: a separating
      ! speed here is a root found on the wrong side, not a landing
      call set_status(status, STATUS_DOMAIN, 'the '//name//'''s landing: it leaves the slide '// &
                      '(normal speed '//format_short(outcome%normal_speed_before)//' m/s) where its gap closed')
      return
    end if
    s = s + matmul(minv_jt, outcome%impulse)
    vn = dot_product(normal, outcome%velocity_after)
    if (vn < close_speed) then
      closed = .true.
      closing_impulse = -vn/dot_product(normal, matmul(k, normal))*normal
      closing_energy = vn**2/(2*dot_product(normal, matmul(k, normal)))
      s = s + matmul(minv_jt, closing_impulse)
    end if
    y(n + 1:2*n) = s
    call m%set_velocities(work, s)
    if (closed .and. abs(point_gap_rate(work, point, foot)) > 1e-9_wp*max(1.0_wp, &
                                                                         abs(outcome%normal_speed_before))) then
      call set_status(status, STATUS_DOMAIN, 'the '//name//'''s landing: the closing left a normal speed of '// &
                      format_short(point_gap_rate(work, point, foot))//' m/s')
    end if
  end subroutine point_impact

  !> The mass matrix of m in its speeds at the positions in `work` (set):
  !> M_ii = 2 T(e_i), M_ij = T(e_i + e_j) - T(e_i) - T(e_j). The velocities
  !> in `work` are left at the last probe's.
  function speeds_mass(m, work) result(mass)
    type(mechanism_t), intent(in) :: m
    type(mechanism_workspace_t), intent(inout) :: work
    real(wp), allocatable :: mass(:, :)
    real(wp), allocatable :: e(:), energy(:)
    real(wp) :: kinetic, potential
    integer :: i, j, n
    n = m%f
    allocate (mass(n, n), e(n), energy(n))
    do i = 1, n
      e = 0
      e(i) = 1
      call m%set_velocities(work, e)
      call m%energy(work, energy(i), potential)
      mass(i, i) = 2*energy(i)
    end do
    do i = 1, n
      do j = i + 1, n
        e = 0
        e(i) = 1
        e(j) = 1
        call m%set_velocities(work, e)
        call m%energy(work, kinetic, potential)
        mass(i, j) = kinetic - energy(i) - energy(j)
        mass(j, i) = mass(i, j)
      end do
    end do
  end function speeds_mass
end module kinetostatics_point_impact
