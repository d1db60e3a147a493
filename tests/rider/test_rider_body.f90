!> The rider's body data: de Leva's shares and lengths scaled to the rider,
!> the grouping into pelvis, legs and trunk, centres of mass and inertias
!> (checked against the whole body assembled segment by segment, written out
!> here independently of rider_body), scaling laws and bad descriptions.
program test_rider_body
  use base_kinds, only: wp
  use base_status, only: status_t
  use rider_body, only: body_params_t, rider_body_t, rigid_body_t, build_rider_body, de_leva_segment, &
    segment_t, SEX_MALE, SEX_FEMALE, SEG_HEAD_NECK, SEG_UPPER_TRUNK, SEG_MIDDLE_TRUNK, SEG_LOWER_TRUNK, &
    SEG_UPPER_ARM, SEG_FOREARM, SEG_HAND, SEG_THIGH, SEG_SHANK, SEG_FOOT, N_SEGMENTS
  use testing, only: check, check_close, check_close_array, finish_tests
  implicit none (type, external)

  ! rtol 1e-13: sums and products of a few dozen numbers of order 1
  real(wp), parameter :: rtol = 1e-13_wp

  call check_male_default()
  call check_female()
  call check_whole_body(SEX_MALE)
  call check_whole_body(SEX_FEMALE)
  call check_scaling()
  call check_bad_descriptions()
  call finish_tests('test_rider_body')

contains

  subroutine check_male_default()
    type(body_params_t) :: p
    type(rider_body_t) :: b
    type(status_t) :: status
    real(wp) :: s, l_th, l_sh, l_lt, legs_x
    call build_rider_body(p, b, status)
    call check(status%ok(), 'male default builds: '//status%text())
    s = 1.78_wp/1.741_wp
    ! METHOD-PART2 B.2: 27.21 / 7.65 / 33.64 kg at 68.5 kg (shares 39.72 / 11.17 / 49.11 %)
    call check_close(b%legs%mass, 0.3972_wp*68.5_wp, rtol, 0.0_wp, 'legs mass 39.72 %')
    call check_close(b%pelvis%mass, 0.1117_wp*68.5_wp, rtol, 0.0_wp, 'pelvis mass 11.17 %')
    call check_close(b%trunk%mass, 0.4911_wp*68.5_wp, rtol, 0.0_wp, 'trunk mass 49.11 %')
    ! hip to heel: thigh + shank = 0.8562 m scaled (B.2: 0.875 m)
    call check_close(b%heel(1), 0.8562_wp*s, rtol, 0.0_wp, 'heel 0.875 m from the hip')
    call check_close(b%heel(3), -0.075_wp, rtol, 0.0_wp, 'heel on the slide')
    l_lt = 0.1457_wp*s
    call check_close(b%hip(1), (1 - 0.6115_wp)*l_lt, rtol, 0.0_wp, 'hip ahead of the pelvis contact')
    call check_close(b%hip(3), 0.075_wp, rtol, 0.0_wp, 'hip at the centre-of-mass height')
    call check_close_array(b%pelvis%com, [0.0_wp, 0.0_wp, 0.075_wp], 0.0_wp, 1e-15_wp, 'pelvis CoM over the contact')
    ! legs CoM by hand: 2 thighs at 40.95 %, 2 shanks at thigh + 44.59 %, 2 feet at the ankle
    l_th = 0.4222_wp*s
    l_sh = 0.4340_wp*s
    legs_x = (14.16_wp*0.4095_wp*l_th + 4.33_wp*(l_th + 0.4459_wp*l_sh) + 1.37_wp*(l_th + l_sh))/19.86_wp
    call check_close(b%legs%com(1), legs_x, rtol, 0.0_wp, 'legs centre of mass')
    call check(all(b%legs%com(2:3) == 0) .and. all(b%trunk%com(2:3) == 0), 'centres of mass on the body axis')
    ! back under the upper trunk's CoM: lower + middle trunk + 70.01 % of the upper trunk from the hip
    call check_close(b%back(1), -(0.1457_wp + 0.2155_wp + 0.7001_wp*0.1707_wp)*s, rtol, 0.0_wp, &
                     'back contact at the shoulder blades')
    call check(b%trunk%com(1) < 0 .and. b%trunk%com(1) > b%back(1), 'trunk CoM between hip and back contact')
  end subroutine check_male_default

  subroutine check_female()
    type(body_params_t) :: p
    type(rider_body_t) :: b
    type(status_t) :: status
    p%sex = SEX_FEMALE
    p%mass = 60
    p%height = 1.65_wp
    call build_rider_body(p, b, status)
    call check(status%ok(), 'female builds')
    ! published shares sum to 99.99 %: normalised so the body weighs what is given
    call check_close(b%pelvis%mass + b%legs%mass + b%trunk%mass, 60.0_wp, rtol, 0.0_wp, 'female total mass')
    call check_close(b%legs%mass, 41.76_wp/99.99_wp*60, rtol, 0.0_wp, 'female legs 41.76 of 99.99 %')
    call check_close(b%heel(1), (0.3685_wp + 0.4323_wp)*1.65_wp/1.735_wp, rtol, 0.0_wp, 'female leg length')
  end subroutine check_female

  !> The whole straight rider assembled from all 17 segment instances (as
  !> placed in docs/rider.md) against the three bodies put together: total
  !> mass, centre of mass and inertia about it.
  subroutine check_whole_body(sex)
    integer, intent(in) :: sex
    type(body_params_t) :: p
    type(rider_body_t) :: b
    type(status_t) :: status
    type(segment_t) :: seg(N_SEGMENTS)
    real(wp) :: s, total_share, m(N_SEGMENTS), l(N_SEGMENTS), x(N_SEGMENTS), h, hip, x_upper, rg(3)
    real(wp) :: mass_a, com_a(3), inertia_a(3, 3), mass_b, com_b(3), inertia_b(3, 3)
    integer :: k, copies
    p%sex = sex
    call build_rider_body(p, b, status)
    do k = 1, N_SEGMENTS
      seg(k) = de_leva_segment(sex, k)
    end do
    s = p%height/merge(1.741_wp, 1.735_wp, sex == SEX_MALE)
    l = seg%length*s
    total_share = sum(seg%mass_percent) + sum(seg(SEG_UPPER_ARM:SEG_FOOT)%mass_percent)
    m = seg%mass_percent/total_share*p%mass
    h = p%com_height
    ! centres of mass along the axis of the pelvis frame (origin at the pelvis contact)
    hip = (1 - seg(SEG_LOWER_TRUNK)%com_percent/100)*l(SEG_LOWER_TRUNK)
    x(SEG_LOWER_TRUNK) = 0
    x(SEG_THIGH) = hip + seg(SEG_THIGH)%com_percent/100*l(SEG_THIGH)
    x(SEG_SHANK) = hip + l(SEG_THIGH) + seg(SEG_SHANK)%com_percent/100*l(SEG_SHANK)
    x(SEG_FOOT) = hip + l(SEG_THIGH) + l(SEG_SHANK)
    x(SEG_MIDDLE_TRUNK) = hip - l(SEG_LOWER_TRUNK) - (1 - seg(SEG_MIDDLE_TRUNK)%com_percent/100)*l(SEG_MIDDLE_TRUNK)
    x_upper = hip - l(SEG_LOWER_TRUNK) - l(SEG_MIDDLE_TRUNK) - &
              (1 - seg(SEG_UPPER_TRUNK)%com_percent/100)*l(SEG_UPPER_TRUNK)
    x(SEG_UPPER_TRUNK) = x_upper
    x(SEG_HEAD_NECK) = hip - l(SEG_LOWER_TRUNK) - l(SEG_MIDDLE_TRUNK) - l(SEG_UPPER_TRUNK) - &
                       (1 - seg(SEG_HEAD_NECK)%com_percent/100)*l(SEG_HEAD_NECK)
    x(SEG_UPPER_ARM:SEG_HAND) = x_upper
    mass_a = 0
    com_a = 0
    do k = 1, N_SEGMENTS
      copies = merge(2, 1, k >= SEG_UPPER_ARM)
      mass_a = mass_a + copies*m(k)
      com_a(1) = com_a(1) + copies*m(k)*x(k)
    end do
    com_a(1) = com_a(1)/mass_a
    com_a(3) = h
    inertia_a = 0
    do k = 1, N_SEGMENTS
      copies = merge(2, 1, k >= SEG_UPPER_ARM)
      rg = seg(k)%gyration_percent/100*l(k)   ! sagittal, transverse, longitudinal
      if (k == SEG_FOOT) then                 ! feet point up: long axis z
        inertia_a(1, 1) = inertia_a(1, 1) + copies*m(k)*rg(1)**2
        inertia_a(3, 3) = inertia_a(3, 3) + copies*m(k)*(rg(3)**2 + (x(k) - com_a(1))**2)
      else
        inertia_a(1, 1) = inertia_a(1, 1) + copies*m(k)*rg(3)**2
        inertia_a(3, 3) = inertia_a(3, 3) + copies*m(k)*(rg(1)**2 + (x(k) - com_a(1))**2)
      end if
      inertia_a(2, 2) = inertia_a(2, 2) + copies*m(k)*(rg(2)**2 + (x(k) - com_a(1))**2)
    end do
    ! the three bodies placed straight: legs and trunk frames at the hip
    call combine(b%pelvis, [0.0_wp, 0.0_wp, 0.0_wp], mass_b, com_b, inertia_b, .true.)
    call combine(b%legs, b%hip, mass_b, com_b, inertia_b, .false.)
    call combine(b%trunk, b%hip, mass_b, com_b, inertia_b, .false.)
    call check_close(mass_b, p%mass, rtol, 0.0_wp, 'whole body mass')
    call check_close(mass_a, p%mass, rtol, 0.0_wp, 'segments mass')
    call check_close_array(com_b, com_a, rtol, 1e-15_wp, 'whole body centre of mass')
    call check_close_array(reshape(inertia_b, [9]), reshape(inertia_a, [9]), 1e-12_wp, 1e-14_wp, &
                           'whole body inertia about its centre of mass')
  end subroutine check_whole_body

  !> Accumulates body `r` placed at `offset` into (mass, com, inertia about com).
  subroutine combine(r, offset, mass, com, inertia, first)
    type(rigid_body_t), intent(in) :: r
    real(wp), intent(in) :: offset(3)
    real(wp), intent(inout) :: mass, com(3), inertia(3, 3)
    logical, intent(in) :: first
    real(wp) :: c(3), total, d1(3), d2(3)
    if (first) then
      mass = r%mass
      com = r%com + offset
      inertia = r%inertia
      return
    end if
    total = mass + r%mass
    c = (mass*com + r%mass*(r%com + offset))/total
    d1 = com - c
    d2 = r%com + offset - c
    inertia = inertia + parallel(mass, d1) + r%inertia + parallel(r%mass, d2)
    mass = total
    com = c
  end subroutine combine

  function parallel(m, d) result(t)
    real(wp), intent(in) :: m, d(3)
    real(wp) :: t(3, 3)
    integer :: i, j
    do j = 1, 3
      do i = 1, 3
        t(i, j) = -m*d(i)*d(j)
      end do
      t(j, j) = t(j, j) + m*dot_product(d, d)
    end do
  end function parallel

  !> 1.25 x the height: every length grows 1.25x, inertias 1.5625x at the same mass;
  !> twice the mass: masses and inertias double, positions stay.
  subroutine check_scaling()
    type(body_params_t) :: p
    type(rider_body_t) :: a, b
    type(status_t) :: status
    call build_rider_body(p, a, status)
    p%height = 1.25_wp*p%height
    p%com_height = 1.25_wp*p%com_height
    call build_rider_body(p, b, status)
    call check(status%ok(), 'taller rider builds')
    call check_close_array(b%heel, 1.25_wp*a%heel, rtol, 0.0_wp, 'height scales the heel')
    call check_close_array(reshape(b%trunk%inertia, [9]), reshape(1.5625_wp*a%trunk%inertia, [9]), rtol, 1e-15_wp, &
                           'height scales inertia by its square')
    p = body_params_t()
    p%mass = 2*p%mass
    call build_rider_body(p, b, status)
    call check_close_array(reshape(b%legs%inertia, [9]), reshape(2*a%legs%inertia, [9]), rtol, 1e-15_wp, &
                           'mass scales inertia')
    call check_close_array(b%legs%com, a%legs%com, rtol, 0.0_wp, 'mass leaves positions')
  end subroutine check_scaling

  subroutine check_bad_descriptions()
    type(body_params_t) :: p
    type(rider_body_t) :: b
    type(status_t) :: status
    p%mass = -70
    call build_rider_body(p, b, status)
    call check(.not. status%ok() .and. index(status%text(), 'mass = -70') > 0, 'negative mass refused: '// &
               status%text())
    p = body_params_t()
    p%height = 0
    status = status_t()
    call build_rider_body(p, b, status)
    call check(.not. status%ok() .and. index(status%text(), 'height') > 0, 'zero height refused')
    p = body_params_t()
    p%com_height = 0
    status = status_t()
    call build_rider_body(p, b, status)
    call check(.not. status%ok() .and. index(status%text(), 'com_height') > 0, 'zero CoM height refused')
  end subroutine check_bad_descriptions
end program test_rider_body
