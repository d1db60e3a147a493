!> The closure in blocks (kinetostatics_closure_blocks) against the unblocked
!> computation (one block, every pass over every element) of the same
!> mechanism: the tower of five rolling paraboloids (inputs/contact/tower5.nml)
!> at its start and after 0.3 s of its motion, and the rider on a straight
!> tube (two loops: heels and back). The structure: the tower has one block
!> per contact (5 dependents and 2 rolling rates), each column of J_x passes
!> over a few elements only, not over the bodies above; the rider has two
!> blocks of 3.
!>
!> Agreement "to rounding": the blocked J_x leaves out entries that are zero
!> in exact arithmetic (a contact's closure does not move when the bodies it
!> joins move together; the full pass gives ~1e-17 there), and the two LUs
!> pivot differently; everything else is the same arithmetic. So J_x agrees to
!> 1e-14 of its largest entry, and the dynamics to the rounding of the
!> solves: 1e-10 relative (condition numbers of J_x and M up to ~1e4 times
!> 1e-16, with margin; a wrong entry or a missed element gives O(1)).
program test_closure_blocks
  use base_kinds, only: wp
  use base_constants, only: pi
  use base_status, only: status_t
  use testing, only: check, finish_tests
  use numerics_event_driver, only: driver_options_t, driver_result_t, drive, DRIVE_END_TIME
  use geometry_tube, only: tube_surface_t, new_straight_tube
  use kinetostatics_mechanism, only: mechanism_t, mechanism_workspace_t
  use contact_model, only: contact_system_t, contact_model_t, build_contact_model, contact_convergence_coefficient
  use rider_model, only: rider_params_t, rider_layout_t, build_rider
  use io_input, only: input_text_t, load_input_file
  use io_contact_config, only: read_contact_config
  implicit none (type, external)

  call check_tower()
  call check_rider()
  call finish_tests('test_closure_blocks')

contains

  subroutine check_tower()
    type(input_text_t) :: input
    type(contact_system_t) :: system
    type(contact_model_t), target :: model
    type(driver_options_t) :: options
    type(driver_result_t) :: result
    type(status_t) :: st
    integer :: f, ns, k, longest
    call load_input_file('inputs/contact/tower5.nml', input, st)
    call read_contact_config(input, system, st)
    call build_contact_model(system, model, st)
    call check(st%ok(), 'tower5 built: '//st%text())
    if (.not. st%ok()) return
    associate (m => model%ode%mechanism)
      f = m%f
      ns = m%ns
      call check(m%blocks%blocked, 'tower5: the closure is blocked')
      call check(m%blocks%block_count() == 5, 'tower5: 5 blocks, one per contact')
      do k = 1, m%blocks%block_count()
        call check(size(m%blocks%blocks(k)%members) == 7 .and. m%blocks%blocks(k)%mb == 5, &
                   'tower5: each block has 5 dependent coordinates and 2 rolling rates')
      end do
      longest = maxval(m%blocks%pass_start(2:) - m%blocks%pass_start(:size(m%blocks%pass_start) - 1))
      print '(a, i0, a, i0, a)', 'tower5: the longest column pass has ', longest, ' of ', m%n_elements, ' elements'
      ! a column reaches its own contact's chain and closure, not the bodies above
      call check(longest <= 10, 'tower5: every column of J_x passes over at most 10 elements')
      ! the mass matrix: speed k of body i moves body i and those above, not those below
      call check(m%blocks%mass_blocked, 'tower5: the mass matrix is built from partial passes')
      associate (length => m%blocks%mass_pass_start(2:) - m%blocks%mass_pass_start(:ns))
        print '(a, 15(1x, i0))', 'tower5: elements of the mass matrix columns:', length
        call check(length(ns) < m%n_elements .and. all(length(1:ns - 3) > length(4:ns)), &
                   'tower5: the columns of higher bodies pass over fewer elements')
      end associate
      call compare(m, 0.0_wp, model%y0(1:f), model%y0(f + 1:f + ns), 'tower5 at the start')
    end associate
    options%t_end = 0.3_wp
    options%output_step = 0.1_wp
    options%progress_seconds = 0
    options%ode%rtol = 1e-11_wp
    options%ode%atol = 1e-10_wp
    call model%ode%start_series(10)
    options%ode%convergence_coefficient = contact_convergence_coefficient   ! as slidesim runs it
    call drive(model%ode, model%y0, options, result, st)
    call check(st%ok() .and. result%outcome == DRIVE_END_TIME, 'tower5 ran 0.3 s: '//st%text())
    associate (m => model%ode%mechanism, series => model%ode%series)
      call compare(m, series%time(series%n), series%q(:, series%n), series%qd(m%speeds, series%n), &
                   'tower5 after 0.3 s')
    end associate
  end subroutine check_tower

  subroutine check_rider()
    type(rider_params_t) :: p
    type(rider_layout_t) :: lay
    type(mechanism_t) :: m
    type(tube_surface_t) :: tube
    type(status_t) :: st
    real(wp) :: q0(3)
    type(mechanism_workspace_t) :: work
    p%u0 = 5
    tube = new_straight_tube(0.5_wp, 15*pi/180, 20.0_wp, st)
    call build_rider(p, tube, m, lay, q0, st)
    call check(st%ok(), 'rider builds: '//st%text())
    if (.not. st%ok()) return
    call check(m%blocks%block_count() == 2, 'rider: 2 blocks (heels, back)')
    if (m%blocks%block_count() == 2) &
      call check(all([size(m%blocks%blocks(1)%members), size(m%blocks%blocks(2)%members)] == 3), &
                 'rider: 3 dependents each')
    call m%check_start(work, q0, st)
    call check(st%ok(), 'rider: the loops close at the start: '//st%text())
    call compare(m, 0.0_wp, q0 + [0.0_wp, 0.05_wp, -0.03_wp], [3.0_wp, 0.4_wp, -0.2_wp], 'rider')
  end subroutine check_rider

  !> Dynamics and J_x of m (blocked) and of its unblocked copy at (t, q, s).
  subroutine compare(m, t, q, s, label)
    type(mechanism_t), intent(inout) :: m
    real(wp), intent(in) :: t, q(:), s(:)
    character(len=*), intent(in) :: label
    type(mechanism_t) :: full
    type(status_t) :: st
    real(wp) :: a_blocked(size(s)), a_full(size(s)), residual
    real(wp), allocatable :: j_blocked(:, :), j_full(:, :), n_blocked(:), lambda_blocked(:), mu_blocked(:), &
      m_blocked(:, :)
    type(mechanism_workspace_t) :: work
    type(mechanism_workspace_t) :: work_full
    integer :: nx
    full = m
    call full%set_blocked(.false.)
    call check(full%blocks%block_count() == 1 .and. .not. full%blocks%blocked, label//': unblocked copy')
    call m%set_blocked(.true.)
    call m%set_recursion(0)   ! the dense path (the tower's recursion forms no M: test_tree_dynamics)
    call m%dynamics(work, t, q, s, a_blocked, st)
    call check(st%ok(), label//': blocked dynamics '//st%text())
    nx = m%r + m%nd
    allocate (j_blocked(nx, nx), j_full(nx, nx))
    call m%blocks%assemble(m%nd > 0, j_blocked)
    m_blocked = work%mass
    call m%evaluate(work, t, q, s, residual, st)   ! the cut forces of the state
    n_blocked = work%normal
    lambda_blocked = work%lambda
    mu_blocked = work%mu
    call full%dynamics(work_full, t, q, s, a_full, st)
    call check(st%ok(), label//': unblocked dynamics '//st%text())
    call full%blocks%assemble(m%nd > 0, j_full)
    call full%evaluate(work_full, t, q, s, residual, st)
    print '(a, 5(a, es9.2))', label, ': |J diff| ', maxval(abs(j_blocked - j_full)), ' of ', maxval(abs(j_full)), &
      ', |qdd diff| ', maxval(abs(a_blocked - a_full)), ' of ', maxval(abs(a_full)), &
      ', |M diff| ', maxval(abs(m_blocked - work_full%mass))
    call check(maxval(abs(j_blocked - j_full)) <= 1e-14_wp*maxval(abs(j_full)), label//': J_x agrees')
    call check(maxval(abs(a_blocked - a_full)) <= 1e-10_wp*maxval(abs(a_full)), label//': accelerations agree')
    call check(maxval(abs(m_blocked - work_full%mass)) <= 1e-12_wp*maxval(abs(work_full%mass)), &
               label//': mass matrices agree')
    call check(maxval(abs(n_blocked - work_full%normal)) <= 1e-10_wp*maxval(abs(work_full%normal)), &
               label//': normal forces agree')
    call check(maxval(abs(lambda_blocked - work_full%lambda)) <= 1e-10_wp*maxval(abs(work_full%lambda)), &
               label//': cut forces agree')
    if (m%nd > 0) call check(maxval(abs(mu_blocked - work_full%mu)) <= 1e-10_wp*maxval(abs(work_full%mu)), &
                             label//': rolling forces agree')
  end subroutine compare
end program test_closure_blocks
