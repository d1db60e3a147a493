!> The equations of motion of a chain of bodies in linear time
!> (kinetostatics_tree, kinetostatics_mechanism_tree) against the dense mass
!> matrix (the same mechanism with set_recursion(0)): towers of n = 1..8
!> rolling paraboloids (scripts/make_contact_inputs.py --tower n) at random
!> states near their start, a branched tree of hinged and sliding bodies at
!> random states, and the energy of a tower run on the recursion.
!>
!> Tolerance: both solve M s' = Q_bar0 for the same M and Q_bar0 (Q_bar0 by
!> the same passes, M formed and factored by Cholesky against the recursion's
!> pivots on 3 x 3 joint blocks): they differ by rounding, bounded by
!> cond(M) eps times a modest factor. The towers' M has cond up to ~1e3
!> (printed), so 1e-12 of the largest |s'| holds with margin for the
!> accelerations; the normal forces are the same linear map of s' (one
!> inverse-dynamics pass against N0 + G s'): 1e-12 of the largest |N|. A
!> wrong motion subspace, a missed element, a wrong shift or sign gives O(1).
!> The structure: the recursion takes every tower of 2 or more bodies (one
!> joint of 3 speeds per body, parents below), the tower of one keeps the
!> dense path; each joint's column passes cover a bounded number of elements
!> (the same for every body above the first), so the cost is linear in n.
program test_tree_dynamics
  use base_kinds, only: wp
  use base_status, only: status_t
  use testing, only: check, finish_tests
  use numerics_event_driver, only: driver_options_t, driver_result_t, drive, DRIVE_END_TIME
  use numerics_linear_algebra, only: lu_factor, lu_reciprocal_condition, one_norm
  use kinetostatics_mechanism, only: mechanism_t, mechanism_workspace_t
  use kinetostatics_joints, only: new_revolute, new_prismatic, new_rigid_offset
  use kinetostatics_mass, only: new_mass_element
  use contact_model, only: contact_system_t, contact_model_t, build_contact_model, contact_convergence_coefficient
  use io_input, only: input_text_t, load_input_file
  use io_contact_config, only: read_contact_config
  implicit none (type, external)

  character(len=*), parameter :: folder = 'build_test_tree_dynamics'
  integer :: n, err
  integer(8) :: seed = 20261130_8

  call execute_command_line('rm -rf '//folder, exitstat=err)
  do n = 1, 8
    call execute_command_line('python3 scripts/make_contact_inputs.py --tower '//decimal(n)//' --folder '//folder// &
                              ' --duration 1', exitstat=err)
    call check(err == 0, 'tower '//decimal(n)//' written')
    if (err == 0) call check_tower(n)
  end do
  call check_energy(6)
  call check_branched_tree()
  call execute_command_line('rm -rf '//folder, exitstat=err)
  call finish_tests('test_tree_dynamics')

contains

  function decimal(k) result(text)
    integer, intent(in) :: k
    character(len=:), allocatable :: text
    character(len=12) :: buffer
    write (buffer, '(i0)') k
    text = trim(buffer)
  end function decimal

  real(wp) function uniform(a, b)
    real(wp), intent(in) :: a, b
    seed = modulo(6364136223846793005_8*seed + 1442695040888963407_8, huge(seed))
    uniform = a + (b - a)*real(modulo(seed/1024_8, 1000003_8), wp)/1000003.0_wp
  end function uniform

  subroutine build(n, model)
    integer, intent(in) :: n
    type(contact_model_t), intent(out), target :: model
    type(input_text_t) :: input
    type(contact_system_t) :: system
    type(status_t) :: st
    call load_input_file(folder//'/tower'//decimal(n)//'.nml', input, st)
    call read_contact_config(input, system, st)
    call build_contact_model(system, model, st)
    call check(st%ok(), 'tower '//decimal(n)//' built: '//st%text())
  end subroutine build

  subroutine check_tower(n)
    integer, intent(in) :: n
    type(contact_model_t), target :: model
    type(mechanism_t) :: dense
    type(mechanism_workspace_t) :: work_tree, work_dense
    type(status_t) :: st
    real(wp), allocatable :: q(:), s(:), a_tree(:), a_dense(:), n_tree(:), lu(:, :)
    integer, allocatable :: pivots(:)
    real(wp) :: err_a, err_n, rcond
    integer :: trial, f, ns, k, b
    character(len=:), allocatable :: label
    label = 'tower '//decimal(n)
    call build(n, model)
    associate (m => model%ode%mechanism)
      f = m%f
      ns = m%ns
      call m%set_recursion(2)
      call check(m%tree%active .eqv. (n >= 2), label//': the recursion takes every tower of two or more')
      if (m%tree%active) then
        call check(m%tree%n_bodies == n .and. all(m%tree%speed_start(2:) - m%tree%speed_start(:n) == 3), &
                   label//': n bodies of 3 speeds each')
        call check(m%tree%parent(1) == 0 .and. all(m%tree%parent(2:) == [(b, b = 1, n - 1)]), &
                   label//': a chain from the table up')
        ! each column passes over its own joint's elements only: the same count for every body above the first
        associate (length => m%tree%pass_start(2:) - m%tree%pass_start(:ns) + &
                             m%tree%second_start(2:) - m%tree%second_start(:ns))
          if (n >= 3) call check(all(length(7:) == length(4:ns - 3)), label//': the same passes for every body '// &
                                 'above the first (linear cost)')
          print '(a, a, 24(1x, i0))', label, ': elements per column:', length(:min(ns, 24))
        end associate
      end if
      dense = m
      call dense%set_recursion(0)
      call check(.not. dense%tree%active, label//': dense copy')
      allocate (a_tree(ns), a_dense(ns))
      do trial = 1, 4
        q = model%y0(1:f)
        s = model%y0(f + 1:f + ns)
        if (trial > 1) then
          do k = 1, f
            q(k) = q(k) + uniform(-0.02_wp, 0.02_wp)
          end do
          do k = 1, ns
            s(k) = uniform(-1.0_wp, 1.0_wp)
          end do
        end if
        call m%dynamics(work_tree, 0.0_wp, q, s, a_tree, st)
        call check(st%ok(), label//': recursion '//st%text())
        n_tree = work_tree%normal
        call dense%dynamics(work_dense, 0.0_wp, q, s, a_dense, st)
        call check(st%ok(), label//': dense '//st%text())
        if (.not. st%ok()) cycle
        lu = work_dense%mass
        allocate (pivots(ns))
        call lu_factor(lu, pivots, st)
        call lu_reciprocal_condition(lu, one_norm(work_dense%mass), rcond, st)
        deallocate (pivots)
        err_a = maxval(abs(a_tree - a_dense))/maxval(abs(a_dense))
        err_n = maxval(abs(n_tree - work_dense%normal))/maxval(abs(work_dense%normal))
        print '(a, a, i0, 3(a, es9.2))', label, ', state ', trial, ': cond(M) ', 1/rcond, ', |qdd diff| ', err_a, &
          ', |N diff| ', err_n
        call check(err_a <= 1e-12_wp, label//': accelerations agree to 1e-12')
        call check(err_n <= 1e-12_wp, label//': normal forces agree to 1e-12')
      end do
    end associate
  end subroutine check_tower

  !> A frictionless rolling tower on the recursion: rolling does no work, the
  !> energy is conserved to the integrator's tolerance. The gentle start
  !> (1 degree of tilt) has little kinetic energy against which the error is
  !> measured; the same run on the dense path shows the integrator's share
  !> (P1, rtol 1e-11: ~6e-8 of the largest kinetic energy over 1 s, the
  !> documented 5e-8 over 10 s). Checked: below 2e-7 and within a factor 2
  !> of the dense path's (a wrong force or acceleration drifts by O(1)).
  subroutine check_energy(n)
    integer, intent(in) :: n
    real(wp) :: error_tree, error_dense
    error_tree = energy_error(n, .true.)
    error_dense = energy_error(n, .false.)
    print '(a, i0, 2(a, es9.2))', 'energy: tower ', n, ': error on the recursion ', error_tree, &
      ', on the dense path ', error_dense
    call check(error_tree <= 2e-7_wp .and. error_tree <= 2*error_dense, &
               'energy: conserved on the recursion as on the dense path')
  end subroutine check_energy

  real(wp) function energy_error(n, recursion) result(error)
    integer, intent(in) :: n
    logical, intent(in) :: recursion
    type(contact_model_t), target :: model
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    type(status_t) :: st
    integer :: k
    error = huge(1.0_wp)
    call build(n, model)
    if (recursion) then
      call model%ode%mechanism%set_recursion(2)
    else
      call model%ode%mechanism%set_recursion(0)
    end if
    call check(model%ode%mechanism%tree%active .eqv. recursion, 'energy: the path asked for')
    options%t_end = 1
    options%output_step = 0.01_wp
    options%progress_seconds = 0
    options%ode%rtol = 1e-11_wp
    options%ode%atol = 1e-10_wp
    options%ode%convergence_coefficient = contact_convergence_coefficient
    call model%ode%start_series(200)
    call drive(model%ode, model%y0, options, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, 'energy: tower ran 1 s: '//st%text())
    associate (s => model%ode%series)
      k = s%n
      if (k < 2) return
      error = maxval(abs(s%kinetic(:k) + s%potential(:k) - s%kinetic(1) - s%potential(1)))/maxval(s%kinetic(:k))
      call check(all(s%normal(:, :k) > 0), 'energy: the contacts press throughout')
    end associate
  end function energy_error

  !> A branched tree without loops: body 1 hinged to the ground about z
  !> carries body 2 (hinged about y at +x) and body 3 (hinged about a tilted
  !> axis at -x); body 2 carries body 4 on a slider. Full inertia tensors,
  !> centres off the frames. cond(M) is printed; 1e-12 as for the towers.
  subroutine check_branched_tree()
    type(mechanism_t) :: m, dense
    type(mechanism_workspace_t) :: work_tree, work_dense
    type(status_t) :: st
    real(wp) :: inertia(3, 3), q(4), s(4), a_tree(4), a_dense(4), err_a
    real(wp), parameter :: gravity(3) = [0.0_wp, 0.0_wp, -9.80665_wp]
    integer :: f1, f1a, f1b, f2, f2a, f3, f4, t1, t2, t3, d4, trial, k
    inertia = reshape([0.05_wp, 0.01_wp, 0.0_wp, 0.01_wp, 0.04_wp, 0.005_wp, 0.0_wp, 0.005_wp, 0.03_wp], [3, 3])
    f1 = m%add_frame('body1')
    t1 = m%add_scalar('theta1')
    call m%add_element(new_revolute('hinge1', 1, f1, t1, [0.0_wp, 0.0_wp, 1.0_wp]))
    call m%add_element(new_mass_element('mass1', f1, 1.5_wp, inertia, [0.1_wp, 0.05_wp, 0.2_wp], gravity, st))
    f1a = m%add_frame('arm_a')
    call m%add_element(new_rigid_offset('arm_a', f1, f1a, [0.5_wp, 0.0_wp, 0.1_wp]))
    f2 = m%add_frame('body2')
    t2 = m%add_scalar('theta2')
    call m%add_element(new_revolute('hinge2', f1a, f2, t2, [0.0_wp, 1.0_wp, 0.0_wp]))
    call m%add_element(new_mass_element('mass2', f2, 0.8_wp, 0.5_wp*inertia, [0.0_wp, 0.1_wp, -0.4_wp], gravity, st))
    f1b = m%add_frame('arm_b')
    call m%add_element(new_rigid_offset('arm_b', f1, f1b, [-0.4_wp, 0.1_wp, 0.0_wp]))
    f3 = m%add_frame('body3')
    t3 = m%add_scalar('theta3')
    call m%add_element(new_revolute('hinge3', f1b, f3, t3, [0.6_wp, 0.0_wp, 0.8_wp]))
    call m%add_element(new_mass_element('mass3', f3, 0.6_wp, 0.3_wp*inertia, [-0.2_wp, 0.0_wp, -0.3_wp], gravity, st))
    f2a = m%add_frame('rail')
    call m%add_element(new_rigid_offset('rail', f2, f2a, [0.0_wp, 0.0_wp, -0.5_wp]))
    f4 = m%add_frame('body4')
    d4 = m%add_scalar('slide4')
    call m%add_element(new_prismatic('slider4', f2a, f4, d4, [1.0_wp, 0.0_wp, 0.0_wp]))
    call m%add_element(new_mass_element('mass4', f4, 0.4_wp, 0.2_wp*inertia, [0.05_wp, 0.05_wp, 0.0_wp], gravity, st))
    call m%set_coordinates([t1, t2, t3, d4])
    call m%finalize(st)
    call check(st%ok(), 'branched tree built: '//st%text())
    if (.not. st%ok()) return
    call m%set_recursion(2)
    call check(m%tree%active .and. m%tree%n_bodies == 4, 'branched tree: the recursion takes it')
    if (m%tree%active) call check(all(m%tree%parent == [0, 1, 1, 2]), 'branched tree: parents 0, 1, 1, 2')
    dense = m
    call dense%set_recursion(0)
    do trial = 1, 4
      do k = 1, 4
        q(k) = uniform(-1.0_wp, 1.0_wp)
        s(k) = uniform(-2.0_wp, 2.0_wp)
      end do
      call m%dynamics(work_tree, 0.0_wp, q, s, a_tree, st)
      call check(st%ok(), 'branched tree: recursion '//st%text())
      call dense%dynamics(work_dense, 0.0_wp, q, s, a_dense, st)
      call check(st%ok(), 'branched tree: dense '//st%text())
      err_a = maxval(abs(a_tree - a_dense))/maxval(abs(a_dense))
      print '(a, i0, a, es9.2)', 'branched tree, state ', trial, ': |qdd diff| ', err_a
      call check(err_a <= 1e-12_wp, 'branched tree: accelerations agree to 1e-12')
    end do
  end subroutine check_branched_tree
end program test_tree_dynamics
