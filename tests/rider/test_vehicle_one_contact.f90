!> A vehicle on one contact (&sled may_fly; rider_vehicle_flight): with one
!> contact open the vehicle is a rigid body on one point contact, five
!> freedoms, the roll about its bar free (issue 26: the double ring in the
!> bowl). A ring (one rider) on a frictionless plane, against closed forms:
!>
!>   level   on its rear contact on a level plane, its front 0.15 m up,
!>           rolled 0.3 rad, every coordinate moving: at every record on
!>           one contact the contact's normal force of the free rigid body
!>           on a fixed plane, N K_nn = -n.g - n.(w x (w x rho))
!>           + k.I^-1 (w x I w), k = rho x n, rho from the centre of mass to
!>           the contact point, K_nn = 1/m + k.I^-1 k (= n.K n of
!>           kinetostatics_impact's rigid_body_delassus), I in world axes
!>           (1e-9 of m g: the evaluation's rounding); at the start its
!>           tipping, the angular acceleration I^-1 (N k - w x I w)
!>           (1e-9 rad/s^2); while on one contact the horizontal velocity
!>           of its centre of mass and its angular momentum about the
!>           vertical through it constant (no horizontal force, no vertical
!>           couple: 1e-9) and the energy (1e-9 of the kinetic). The front
!>           lands (plastic): the roll's rate stops, then the impact; from
!>           then on the energy plus the landings' losses is the start's
!>           energy (1e-9), positions continuous through every switch.
!>   tilted  on its front contact on a plane tilted by 20 deg, its rear
!>           0.1 m up, rolled 0.2 rad, moving: the front's normal force as
!>           above; the centre of mass's motion along the plane the
!>           projectile's of gravity's part along it (1e-9 m); the energy;
!>           the rear lands, then the energy balance with the losses.
!> With the roll held (the sled's model, before) the normal force differs
!> by the held roll's couple and the tipping by its roll (a failing check).
program test_vehicle_one_contact
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use base_vector, only: cross
  use testing, only: check, check_close, finish_tests
  use geometry_surface, only: surface_t
  use geometry_elementary, only: plane_t
  use numerics_event_driver, only: driver_result_t
  use kinetostatics_recorder, only: mechanism_series_t
  use kinetostatics_impact, only: rigid_body_delassus
  use rider_vehicle, only: vehicle_body_t, vehicle_body
  use rider_vehicle_flight, only: vehicle_flight_ode_t, drive_vehicle
  use vehicle_fixtures, only: flying_ring, on_contacts, centre, quiet_options
  implicit none (type, external)

  real(wp), parameter :: g = 9.80665_wp

  ! level: rear on (mask 2), front up 0.15 m on a ring of length 0.9 m
  call one_contact('level', 0.0_wp, 2, [0.0_wp, 0.0_wp, 0.0_wp, -asin(0.15_wp/0.9_wp), 0.0_wp, 0.3_wp], &
                   [0.5_wp, 0.2_wp, 0.8_wp, -0.3_wp, 0.0_wp, 0.6_wp])
  ! tilted: front on (mask 1), rear up 0.1 m (the pitch solved by the front's closure)
  call one_contact('tilted', 20.0_wp, 1, [0.0_wp, 0.0_wp, 0.1_wp, 0.0_wp, 0.1_wp, 0.2_wp], &
                   [1.0_wp, -0.2_wp, 0.5_wp, 0.0_wp, 0.2_wp, -0.4_wp])
  call finish_tests('test_vehicle_one_contact')

contains

  !> A ring on a plane tilted by `slope` (deg, about y: u downhill) on the
  !> one contact of open mask `mask`, from the full layout's q, qd (a solved
  !> coordinate's entries unused), driven 1 s (see the header).
  subroutine one_contact(label, slope, mask, q, qd)
    character(len=*), intent(in) :: label
    real(wp), intent(in) :: slope, q(6), qd(6)
    integer, intent(in) :: mask
    type(vehicle_body_t) :: vb
    class(surface_t), allocatable :: plane
    type(vehicle_flight_ode_t), target :: sys
    type(driver_result_t) :: result
    type(status_t) :: st
    real(wp), allocatable :: q0(:), qd0(:), y(:)
    real(wp) :: a, n(3), grav(3), g_t(3), residual, n_exact, alpha(3), w(3), rot(3, 3), inertia(3, 3)
    real(wp) :: c0(3), vc0(3), lz0, e0, c(3), vc(3), tau, worst_n, worst_h, worst_l, worst_e, worst_b, worst_p
    real(wp) :: worst_q, rho(3), roll_span(2)
    integer :: i, f, on, records, landing
    a = slope*pi/180
    n = [sin(a), 0.0_wp, cos(a)]
    grav = [0.0_wp, 0.0_wp, -g]
    g_t = grav - n*dot_product(n, grav)
    plane = plane_t([0.0_wp, 0.0_wp, 0.0_wp], [cos(a), 0.0_wp, -sin(a)], [0.0_wp, 1.0_wp, 0.0_wp], st)
    call flying_ring(plane, 0.0_wp, sys, q0, qd0, st)
    call check(st%ok(), label//': the builds: '//st%text())
    if (.not. st%ok()) return
    call vehicle_body(sys%vehicle, vb, st)
    on = 3 - mask   ! the contact on: 1 the rear, 2 the front
    ! the state on one contact; the mechanism evaluated there
    y = on_contacts(sys, mask, q, qd)
    f = sys%mechanism%f
    call check(f == 5, label//': five coordinates on one contact')
    call sys%mechanism%evaluate(sys%work, 0.0_wp, y(1:f), y(f + 1:2*f), residual, st)
    call check(st%ok(), label//': the start: '//st%text())
    if (.not. st%ok()) return
    sys%margin_work = sys%work
    ! the tipping at the start: the free body's angular acceleration
    associate (bar => sys%work%frames(sys%point(1)))
      rot = bar%rot
      w = bar%omega
      inertia = matmul(rot, matmul(vb%body%inertia, transpose(rot)))
      rho = sys%work%frames(sys%point(on))%r - (bar%r + matmul(rot, vb%body%com))
      n_exact = normal_force(vb%body%mass, inertia, rho, n, grav, w)
      call check_close(sys%work%normal_force(sys%contact(on)), n_exact, 0.0_wp, 1e-9_wp*vb%body%mass*g, &
                       label//': the start''s normal force, the free rigid body''s')
      alpha = solve3(inertia, n_exact*cross(rho, n) - cross(w, matmul(inertia, w)))
      print '(a, es12.4, a, 3f10.4)', label//': at the start N = ', n_exact, ' N, tipping (rad/s^2) ', alpha
      call check(maxval(abs(bar%alpha - alpha)) <= 1e-9_wp*max(1.0_wp, maxval(abs(alpha))), &
                 label//': the start''s tipping, the free rigid body''s')
    end associate
    call drive_vehicle(sys, y, quiet_options(1e-12_wp, 1e-12_wp, 0.01_wp, 1.0_wp, 0.01_wp), result, st)
    print '(a)', label//': '//sys%outcome
    call check(st%ok(), label//': runs: '//st%text())
    if (.not. st%ok()) return
    associate (s => sys%series, open => sys%open_record)
      c0 = centre(s, vb%body%com, 1)
      vc0 = s%body_v(:, 1, 1) + cross(s%body_omega(:, 1, 1), c0 - s%body_r(:, 1, 1))
      lz0 = spin_z(s, vb, 1)
      e0 = s%kinetic(1) + s%potential(1)
      worst_n = 0
      worst_h = 0
      worst_l = 0
      worst_e = 0
      worst_b = 0
      worst_p = 0
      worst_q = 0
      records = 0
      roll_span = [huge(1.0_wp), -huge(1.0_wp)]
      landing = 0
      do i = 1, s%n
        ! the energy balance with the landings' losses, every record
        worst_b = max(worst_b, abs(s%kinetic(i) + s%potential(i) + sys%losses(i) - e0)/s%kinetic(1))
        if (i > 1) then
          if (s%time(i) == s%time(i - 1)) then   ! a switch: the pose and the coordinates continuous
            worst_p = max(worst_p, maxval(abs(s%body_r(:, 1, i) - s%body_r(:, 1, i - 1))), &
                          maxval(abs(s%body_rot(:, :, 1, i) - s%body_rot(:, :, 1, i - 1))))
            worst_q = max(worst_q, maxval(abs(s%q(:, i) - s%q(:, i - 1))))
          end if
        end if
        if (landing == 0 .and. open(i) /= mask) landing = i
        if (landing /= 0) cycle
        ! on one contact, before the landing
        roll_span = [min(roll_span(1), s%q(6, i)), max(roll_span(2), s%q(6, i))]
        records = records + 1
        rot = s%body_rot(:, :, 1, i)
        w = s%body_omega(:, 1, i)
        inertia = matmul(rot, matmul(vb%body%inertia, transpose(rot)))
        c = centre(s, vb%body%com, i)
        rho = s%body_r(:, 1, i) + merge(0.0_wp, vb%length, on == 1)*rot(:, 1) - c
        worst_n = max(worst_n, abs(s%normal(sys%contact(on), i) - normal_force(vb%body%mass, inertia, rho, n, &
                                                                               grav, w)))
        vc = s%body_v(:, 1, i) + cross(w, c - s%body_r(:, 1, i))
        tau = s%time(i) - s%time(1)
        if (slope == 0) then
          worst_h = max(worst_h, norm2(vc(1:2) - vc0(1:2)))
          worst_l = max(worst_l, abs(spin_z(s, vb, i) - lz0))
        else
          worst_h = max(worst_h, norm2(along(c - (c0 + vc0*tau + g_t*tau**2/2), n)))
        end if
        worst_e = max(worst_e, abs(s%kinetic(i) + s%potential(i) - e0)/s%kinetic(1))
      end do
      print '(a, i0, a, 5es10.2)', label//': ', records, ' records on one contact: N (N), '// &
        trim(merge('horizontal speed (m/s), vertical spin', 'motion along the plane (m)           ', slope == 0))// &
        ', energy off by ', worst_n, worst_h, worst_l, worst_e
      print '(a, 2f9.4, a, 3es10.2)', label//': roll from, to (rad) ', roll_span, '; energy balance, pose, '// &
        'coordinates at the switches off by ', worst_b, worst_p, worst_q
      call check(records >= 10, label//': ten records or more on one contact')
      call check(landing > 0, label//': the contact in the air lands')
      call check(roll_span(2) - roll_span(1) > 0.01_wp, label//': the roll turns (free; held it would not move)')
      call check(worst_n <= 1e-9_wp*vb%body%mass*g, label//': the normal force of the free rigid body on a plane')
      if (slope == 0) then
        call check(worst_h <= 1e-9_wp, label//': the horizontal velocity of the centre of mass constant')
        call check(worst_l <= 1e-9_wp, label//': the angular momentum about the vertical constant')
      else
        call check(worst_h <= 1e-9_wp, label//': the centre of mass along the plane a projectile')
      end if
      call check(worst_e <= 1e-9_wp, label//': the energy conserved on one contact')
      call check(worst_b <= 1e-9_wp, label//': the energy plus the landings'' losses conserved')
      call check(worst_p <= 1e-9_wp .and. worst_q <= 1e-9_wp, label//': the pose continuous through the switches')
      call check(sys%flights%landings >= 1, label//': a landing counted')
      if (sys%flights%landings >= 1) call check(sys%flights%landing(1)%contact == mask, &
                                                label//': the contact in the air lands')
    end associate
  end subroutine one_contact

  !> The normal force (N) at a frictionless point contact of a fixed plane
  !> (normal n) on a free rigid body (mass m, inertia about its centre of
  !> mass in world axes, angular velocity w), rho from its centre of mass to
  !> the contact point, under gravity grav: the contact point's normal
  !> acceleration zero (the header).
  real(wp) function normal_force(m, inertia, rho, n, grav, w) result(force)
    real(wp), intent(in) :: m, inertia(3, 3), rho(3), n(3), grav(3), w(3)
    real(wp) :: k(3), k_nn, kk(3, 3)
    k = cross(rho, n)
    kk = rigid_body_delassus(m, inertia, rho)
    k_nn = dot_product(n, matmul(kk, n))
    force = (-dot_product(n, grav) - dot_product(n, cross(w, cross(w, rho))) + &
             dot_product(k, solve3(inertia, cross(w, matmul(inertia, w)))))/k_nn
  end function normal_force

  !> x solving a x = b (Cramer's rule; a symmetric positive definite 3 x 3).
  function solve3(a, b) result(x)
    real(wp), intent(in) :: a(3, 3), b(3)
    real(wp) :: x(3), det
    det = dot_product(a(:, 1), cross(a(:, 2), a(:, 3)))
    x(1) = dot_product(b, cross(a(:, 2), a(:, 3)))/det
    x(2) = dot_product(a(:, 1), cross(b, a(:, 3)))/det
    x(3) = dot_product(a(:, 1), cross(a(:, 2), b))/det
  end function solve3

  !> The part of x along the plane of normal n.
  function along(x, n) result(p)
    real(wp), intent(in) :: x(3), n(3)
    real(wp) :: p(3)
    p = x - n*dot_product(n, x)
  end function along

  !> The vertical component of the angular momentum about the centre of
  !> mass at record i (R I R^T w).
  real(wp) function spin_z(s, vb, i)
    type(mechanism_series_t), intent(in) :: s
    type(vehicle_body_t), intent(in) :: vb
    integer, intent(in) :: i
    real(wp) :: l(3), rot(3, 3)
    rot = s%body_rot(:, :, 1, i)
    l = matmul(rot, matmul(vb%body%inertia, matmul(transpose(rot), s%body_omega(:, 1, i))))
    spin_z = l(3)
  end function spin_z
end program test_vehicle_one_contact
