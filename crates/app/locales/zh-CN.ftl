### integrators

integrators-join = { "；" }
integrators-legend-dp45-order = DP45：{ $order }
integrators-overflow-note = 在 t = { $time } 处溢出
integrators-failed = 失败
integrators-stable-yes = 是
integrators-stable-no = 否
integrators-method-euler = 显式欧拉法
integrators-method-symplectic-euler = 辛欧拉法
integrators-method-heun = Heun 法
integrators-method-rk4 = RK4 法
integrators-legend-symplectic-euler = 辛欧拉 ×
integrators-legend-dp45 = DP45 ● 步
integrators-legend-growing = { $legend } ×{ $growth }/步 ↑
integrators-legend-order = { $legend }：{ $order }
integrators-legend-no-fit = { $legend }：无拟合
integrators-legend-dp45-no-order = DP45：无阶数
integrators-series-exact = 精确解
integrators-axis-error = 误差 |x_num − x_exact|
integrators-axis-step = 步长 h
integrators-axis-max-error = 最大误差
integrators-axis-re = 实部 Re(hλ)
integrators-axis-im = 虚部 Im(hλ)
integrators-axis-evaluations = 右端函数求值次数 N
integrators-limit-up-to = 当 h ≤ { $step } 时稳定
integrators-limit-every = 对任意 h 稳定
integrators-limit-none = 对任意 h 都不稳定
integrators-method-overflows = { $method }在 t = { $time } 处溢出（每步 ×{ $growth }）
integrators-method-diverges = { $method }发散（每步 ×{ $growth }），最大误差 { $error }
integrators-method-diverges-clipped = { $method }发散（每步 ×{ $growth }，已截断），最大误差 { $error }
integrators-method-bounded = { $method }保持有界（每步 ×{ $growth }），最大误差 { $error }
integrators-dp45-words = DP45 走了 { $steps } 步（容差 { $tolerance }），最大误差 { $error }
integrators-dp45-failed = DP45 失败：{ $reason }
integrators-failed-underflow = 在 t = { $time } 处步长变得过小，无法继续推进（问题可能过于刚性或奇异）
integrators-failed-max-steps = 在 t = { $time } 处放弃，共 { $steps } 步
integrators-failed-non-finite = 在 t = { $time } 处解变为无穷大或无定义（请尝试更小的步长）
integrators-describe-response = 各方法与精确的衰减振荡对比，时长 { $duration }，h = { $step }（{ $steps } 步）。{ $methods }。图中显示精确振幅的 ±{ $range } 倍范围；超出的曲线在边缘处截断。
integrators-describe-response-last = 各方法与精确的衰减振荡对比，时长 { $duration }，h = { $step }（{ $steps } 步，最后一步为 { $last }，恰好结束于 T）。{ $methods }。图中显示精确振幅的 ±{ $range } 倍范围；超出的曲线在边缘处截断。
integrators-error-peak = { $method }：最大 { $error }，位于 t = { $time }
integrators-error-peak-growing = { $method }：最大 { $error }，位于 t = { $time }，且在增长
integrators-error-none = { $method }：没有有限误差
integrators-error-no-method = 未开启任何方法。
integrators-describe-error = 误差 |x_num − x_exact|，对数坐标，取各方法自身的网格点（h = { $step }）：{ $methods }。
integrators-describe-error-clipped = 误差 |x_num − x_exact|，对数坐标，取各方法自身的网格点（h = { $step }）：{ $methods }。超过 { $clip } 的误差在顶部截断。
integrators-fit = { $method }：拟合斜率 { $slope }（h = { $from } … { $to }）
integrators-fit-overflows = { $method }：拟合斜率 { $slope }（h = { $from } … { $to }），h ≥ { $limit } 时溢出
integrators-no-fit = { $method }：无拟合（渐近区间内的点太少）
integrators-no-fit-overflows = { $method }：无拟合（渐近区间内的点太少），h ≥ { $limit } 时溢出
integrators-slope = 斜率 { $order }
integrators-describe-convergence = { $points } 个公共检查点上的最大误差随步长 h 的变化，最多 { $levels } 个步长，从 { $from } 起逐次减半（每种方法总计最多 { $budget } 步，显式欧拉法最多 { $euler_budget } 步；更细的步长略去）。{ $methods }。每个阶数只在渐近区间内拟合，以粗线段表示：即局部斜率相差不超过 { $spread } 的最细步长，且误差低于 x₀ 的 { $ceiling }、高于 x₀ 的 1e-10。参考斜率 1 和 4 为点线；当前 h 为竖直虚线。DP45 没有单一的 h：见计算量–精度图。
integrators-off-scale = { $name } = { $value }（超出范围）
integrators-path = h 增大时 hλ 的轨迹
integrators-z-real-pair = z = hλ = { $z1 } 和 { $z2 }
integrators-region-inside = { $method }：在其稳定区域内，|R| = { $growth }，{ $limit }
integrators-region-outside = { $method }：在其稳定区域外，|R| = { $growth }，{ $limit }
integrators-describe-stability = z = hλ 复平面上的稳定区域 |R(z)| ≤ 1（各闭合曲线的内部；显式欧拉法的是圆盘 |1 + z| ≤ 1）。h = { $step } 时系统的两个极点给出 { $z }。{ $methods }。辛欧拉法不是标量映射 R(z)：它的 2×2 步进矩阵此时的谱半径为 { $radius }，{ $limit }。DP45 自行选择步长并保持稳定。
integrators-work-words = { $method }：从 { $error_first }（{ $work_first } 次求值）到 { $error_last }（{ $work_last } 次求值）
integrators-describe-work = 最大误差与所花计算量的关系，计算量以右端函数 f 的求值次数计，双对数坐标，包含所有方法：定步长方法取收敛性研究中的各步长（误差取其公共检查点），DP45 取容差 { $from } … { $to }（误差取其接受的各步）。越低越精确，越靠左越省；p 阶方法以斜率 −p 下降；DP45 的各次计算中，由容差决定步长的画为圆点，由稳定性决定步长的画为叉号。{ $methods }。
integrators-dp45-stability-runs = 步长由稳定性决定的计算（超过 { $share } 的步长达到其最大稳定步长的 { $fraction } 或以上）：{ $count }/{ $runs }
integrators-dp45-order = DP45 观测阶数 { $order }（在 { $from } … { $to } 次求值范围内拟合，此处步长由容差决定）；{ $runs }
integrators-dp45-no-order = DP45 没有观测阶数：步长由稳定性决定，或渐近区间内剩余的计算太少；{ $runs }
integrators-title = 数值积分方法及其误差
integrators-summary = 用显式欧拉法、辛欧拉法、Heun 法（RK2）和经典 RK4 以固定步长 h 积分自由振子，并用自适应步长的 Dormand–Prince 5(4) 积分，各自与精确解比较。单步法每一步把每个模态乘以 R(hλ)：当 |R| > 1 时，无论方法对方程拟合得多好，数值都会增长，这就是为什么除非 h < 2ζ/ωₙ，显式欧拉法会让轻阻尼振子发散。方法稳定时，把 h 减半会使误差除以 2^p，其中 p 是方法的收敛阶：收敛图测量的就是 p。关闭某个方法会隐藏其曲线，但其读数仍会计算。
integrators-param-zeta = 阻尼比
integrators-param-wn = 固有频率
integrators-param-h = 步长
integrators-param-T = 时长
integrators-param-x0 = 初始位移
integrators-param-tol = DP45 容差（相对；绝对容差为 tol·x₀）
integrators-param-euler = 显式欧拉法
integrators-param-symplectic-euler = 辛欧拉法
integrators-param-heun = Heun 法（RK2）
integrators-param-rk4 = RK4
integrators-param-dp45 = Dormand–Prince 5(4)，自适应
integrators-readout-h-used = 实际步长：恰为 h（较短的最后一步使计算结束于 T）
integrators-readout-h-last = 最后一步，使计算结束于 T
integrators-readout-max-err-euler = 最大误差，显式欧拉法
integrators-readout-max-err-symplectic-euler = 最大误差，辛欧拉法
integrators-readout-max-err-heun = 最大误差，Heun 法
integrators-readout-max-err-rk4 = 最大误差，RK4
integrators-readout-max-err-dp45 = 最大误差，DP45
integrators-readout-order-euler = 拟合阶数，显式欧拉法
integrators-readout-order-symplectic-euler = 拟合阶数，辛欧拉法
integrators-readout-order-heun = 拟合阶数，Heun 法
integrators-readout-order-rk4 = 拟合阶数，RK4
integrators-readout-order-dp45 = 观测阶数，DP45（误差对 f 求值次数，此处步长由容差决定）
integrators-readout-stable-euler = 此 h 下是否稳定，显式欧拉法
integrators-readout-stable-symplectic-euler = 此 h 下是否稳定，辛欧拉法
integrators-readout-stable-heun = 此 h 下是否稳定，Heun 法
integrators-readout-stable-rk4 = 此 h 下是否稳定，RK4
integrators-readout-growth-euler = 每步增长 |R(hλ)|，显式欧拉法
integrators-readout-growth-symplectic-euler = 每步增长（谱半径），辛欧拉法
integrators-readout-growth-heun = 每步增长 |R(hλ)|，Heun 法
integrators-readout-growth-rk4 = 每步增长 |R(hλ)|，RK4
integrators-readout-steps-dp45 = DP45 接受的步数
integrators-plot-response = 数值解与精确解 x(t)
integrators-plot-error = 误差随时间的变化
integrators-plot-convergence = 收敛性：最大误差随步长 h 的变化
integrators-plot-work = 计算量–精度：最大误差随 f 求值次数的变化
integrators-plot-stability = 稳定区域与 z = hλ
integrators-preset-1 = 轻阻尼，h = 0.3 s
integrators-preset-2 = 欧拉法刚好稳定，h = 0.04 s
integrators-preset-3 = RK4 超出其极限，h = 1.6 s
integrators-preset-4 = 无阻尼，h = 0.1 s
integrators-preset-5 = 刚性过阻尼 ζ = 2，ωₙ = 20
integrators-table-caption = 各种方法
integrators-table-column-1 = 方法
integrators-table-column-2 = 阶数 p
integrators-table-column-3 = 每步 f 求值次数
integrators-table-column-4 = 放大因子 R(z)
integrators-table-column-5 = 用于无阻尼振子时
integrators-table-euler-1 = 显式欧拉法
integrators-table-euler-2 = 1
integrators-table-euler-3 = 1
integrators-table-euler-4 = 1 + z
integrators-table-euler-5 = 总是增长：|R(iωh)| = √(1 + ω²h²) > 1
integrators-table-symplectic-euler-1 = 辛欧拉法
integrators-table-symplectic-euler-2 = 1
integrators-table-symplectic-euler-3 = 2
integrators-table-symplectic-euler-4 = 2×2 矩阵，而非标量 R
integrators-table-symplectic-euler-5 = ωh ≤ 2 时能量误差有界
integrators-table-heun-1 = Heun 法（RK2）
integrators-table-heun-2 = 2
integrators-table-heun-3 = 2
integrators-table-heun-4 = 1 + z + z²/2
integrators-table-heun-5 = 缓慢增长：|R(iy)|² = 1 + y⁴/4
integrators-table-rk4-1 = 经典 RK4
integrators-table-rk4-2 = 4
integrators-table-rk4-3 = 4
integrators-table-rk4-4 = 1 + z + z²/2 + z³/6 + z⁴/24
integrators-table-rk4-5 = ωh ≤ 2√2 时略有衰减
integrators-table-dp45-1 = Dormand–Prince 5(4)
integrators-table-dp45-2 = 5
integrators-table-dp45-3 = 6（首级即上一步末级，FSAL）
integrators-table-dp45-4 = 自适应：h 随误差估计调整
integrators-table-dp45-5 = 稳定：被拒绝的步会缩小 h

### nonlinear

nonlinear-effect-linear = 线性
nonlinear-effect-hardening = 渐硬弹簧
nonlinear-effect-softening = 渐软弹簧
nonlinear-effect-stick-slip = 粘滑
nonlinear-effect-bump-stop = 限位块撞击
nonlinear-effect-asymmetric = 非对称阻尼器
nonlinear-effect-several = 多种同时存在
nonlinear-effect-escaped = 逃逸
nonlinear-join = { "；" }
nonlinear-differ = 最大相差 { $deviation }，出现在 t = { $time }
nonlinear-first-swing = 第一次摆动 { $nonlinear }，线性为 { $linear }（比值 { $ratio }）
nonlinear-sticks-at = 从 { $time } 起摩擦力把质量保持在 { $position }
nonlinear-escapes = 非线性计算在 { $time } 时离开图形范围（|x| > { $limit }）
nonlinear-describe-response = { $effect }：两者同时出发；{ $clauses }。
nonlinear-describe-phase = 相平面：两条轨迹都从 x = { $x0 }、v = { $v0 } 出发。线性轨迹螺旋趋向（{ $x_linear }，{ $v_linear }）；非线性轨迹终止于 x = { $x_end }、v = { $v_end }，其最大速度为 { $speed }，线性为 { $speed_linear }。
nonlinear-describe-spring = 恢复力随伸长量的变化，范围 ±{ $reach }：线性弹簧为直线 k·x；在最大行程 { $travel } 处，非线性力为 { $force }，线性为 { $linear }。
nonlinear-describe-spring-stops = 恢复力随伸长量的变化，范围 ±{ $reach }：线性弹簧为直线 k·x；在最大行程 { $travel } 处，非线性力为 { $force }，线性为 { $linear }，超出 ±{ $gap } 后限位块再增加 { $rate }。
nonlinear-describe-damper = 阻尼力加摩擦力随速度的变化，范围 ±{ $speed }：在 +{ $speed }（回弹）时为 { $rebound }，在 −{ $speed }（压缩）时为 { $compression }；线性模型的平均阻尼给出 ±{ $linear }。
nonlinear-describe-damper-friction = 阻尼力加摩擦力随速度的变化，范围 ±{ $speed }：在 +{ $speed }（回弹）时为 { $rebound }，在 −{ $speed }（压缩）时为 { $compression }；线性模型的平均阻尼给出 ±{ $linear }；滑动摩擦在 v = 0 处造成 ±{ $friction } 的跳变，静止时静摩擦最多能保持 ±{ $holding }。
nonlinear-axis-velocity-rebound = 速度 v（+ 为回弹）
nonlinear-series-stops = 限位块 ±{ $gap }
nonlinear-series-linear = 线性模型
nonlinear-series-nonlinear = 非线性（RK4）
nonlinear-marker-sticks = 粘住
nonlinear-marker-start = 起点
nonlinear-series-linear-spring = 线性 k·x
nonlinear-series-spring = k·x + k₃·x³ + 限位块
nonlinear-series-linear-damper = 线性 c̄·v
nonlinear-series-damper = 阻尼器 + 摩擦
nonlinear-schematic = t = { $time } 时的四分之一车辆：悬架伸长 { $extension }。
nonlinear-schematic-pressing = t = { $time } 时的四分之一车辆：悬架伸长 { $extension }，正压在限位块上。
nonlinear-schematic-clear = t = { $time } 时的四分之一车辆：悬架伸长 { $extension }，未接触限位块。
nonlinear-title = 超越线性模型
nonlinear-summary = 真实的悬架只在小幅运动时才是线性的。这里的四分之一车辆模型带有三次弹簧（k₃ > 0 为渐硬，k₃ < 0 为渐软）、回弹（x′ > 0）比压缩更硬的阻尼器、关节中的库仑摩擦以及超出 ±gap 后起作用的橡胶限位块。摩擦会交替粘住和滑动：质量滑动时，摩擦以力 F_c 拖拽它；一旦停下，静摩擦最多能以 F_static（F_c 的固定倍数）将其保持住，只有弹簧拉力更大时它才会再次运动。运动用 RK4 积分，每次停止都在其步长内精确定位，并与从同一初始状态出发的线性模型 m·x″ + c̄·x′ + k·x = 0（c̄ 为平均阻尼系数）对比绘制。请观察预测在哪里失效：周期取决于振幅（渐硬弹簧使其缩短，渐软弹簧使其变长），摩擦使振幅按直线下降，然后把质量永久地保持在偏离中心的位置（粘滑），限位块把平滑的摆动变成撞击，非对称阻尼器会使平均位置偏移。默认值是一个合理的车辆角：300 kg、24 kN/m（1.4 Hz）、1 500 N·s/m 的阻尼器（ζ ≈ 0.28）和略带渐进特性的弹簧。x 是悬架相对静平衡位置的伸长量（正值 = 车身向上）。
nonlinear-param-m = 簧上质量
nonlinear-param-k = 线性弹簧刚度
nonlinear-param-k3 = 弹簧三次项系数（+ 渐硬，− 渐软）
nonlinear-param-c-comp = 压缩阻尼系数
nonlinear-param-c-reb = 回弹阻尼系数
nonlinear-param-friction = 滑动时的库仑摩擦力
nonlinear-param-stick-ratio = 静摩擦与滑动摩擦之比
nonlinear-param-gap = 限位块间隙
nonlinear-param-k-stop = 限位块刚度（0 = 无限位块）
nonlinear-param-x0 = 初始伸长量
nonlinear-param-v0 = 初始速度
nonlinear-readout-effect = 主要非线性
nonlinear-readout-period-ratio = 第一次摆动的周期比 T_nonlinear / T_linear
nonlinear-readout-max-deviation = 最大 |x_nonlinear − x_linear|
nonlinear-readout-period-nonlinear = 第一个完整摆动的非线性周期（三次过零）
nonlinear-readout-period-linear = 第一个完整摆动的线性周期（= 2π/ω_d）
nonlinear-readout-max-travel = 最大 |x|（非线性）
nonlinear-readout-stick-position = 摩擦力将质量保持在
nonlinear-plot-response = 非线性与线性响应 x(t)
nonlinear-plot-phase = 相平面（x, v）
nonlinear-plot-spring = 弹簧与限位块力
nonlinear-plot-damper = 阻尼力与摩擦力
nonlinear-preset-1 = 线性（全部关闭）
nonlinear-preset-2 = 渐硬弹簧
nonlinear-preset-3 = 渐软弹簧
nonlinear-preset-4 = 摩擦粘滑
nonlinear-preset-5 = 限位块撞击
nonlinear-preset-6 = 非对称阻尼器
nonlinear-table-caption = 线性模型在哪里失效
nonlinear-table-column-1 = 非线性
nonlinear-table-column-2 = 力的规律
nonlinear-table-column-3 = 线性模型遗漏了什么
nonlinear-table-column-4 = 图中的特征
nonlinear-table-linear-1 = 无（线性）
nonlinear-table-linear-2 = k·x + c·x′
nonlinear-table-linear-3 = 无：模型是精确的
nonlinear-table-linear-4 = 两条曲线重合
nonlinear-table-hardening-spring-1 = 渐硬弹簧
nonlinear-table-hardening-spring-2 = k·x + k₃·x³，k₃ > 0
nonlinear-table-hardening-spring-3 = 频率随振幅升高
nonlinear-table-hardening-spring-4 = 摆动大时周期较短；两条曲线逐渐分开
nonlinear-table-softening-spring-1 = 渐软弹簧
nonlinear-table-softening-spring-2 = k·x + k₃·x³，k₃ < 0
nonlinear-table-softening-spring-3 = 频率随振幅降低；超过 √(−k/k₃) 后弹簧失去支撑
nonlinear-table-softening-spring-4 = 周期较长；初始值大时可能逃逸
nonlinear-table-stick-slip-1 = 库仑摩擦
nonlinear-table-stick-slip-2 = 滑动时为 F_c·sgn(x′)；静止时最大 F_static
nonlinear-table-stick-slip-3 = 振幅每周期按直线下降约 4F_c/k，随后质量在 |k·x| ≤ F_static 处永久粘住
nonlinear-table-stick-slip-4 = 直线包络；末端平直且不在零点
nonlinear-table-bump-stop-impact-1 = 限位块
nonlinear-table-bump-stop-impact-2 = 超出 ±gap 后为 k_stop·(|x| − gap)
nonlinear-table-bump-stop-impact-3 = 突然的刚性接触：力大、反向快
nonlinear-table-bump-stop-impact-4 = 峰值在 ±gap 处被削平；相图回线出现折角
nonlinear-table-asymmetric-damper-1 = 非对称阻尼器
nonlinear-table-asymmetric-damper-2 = 回弹时为 c_r·x′，压缩时为 c_c·x′
nonlinear-table-asymmetric-damper-3 = 平均位置偏移（“顶升”效应）且半周期不相等
nonlinear-table-asymmetric-damper-4 = 衰减不对称；相图螺线偏离中心
nonlinear-table-several-at-once-1 = 多种同时存在
nonlinear-table-several-at-once-2 = 以上各项之和
nonlinear-table-several-at-once-3 = 各效应相互叠加并相互作用
nonlinear-table-several-at-once-4 = 见各行
nonlinear-table-escaped-1 = 超出极限的渐软弹簧
nonlinear-table-escaped-2 = 当 |x| > √(−k/k₃) 时 k·x + k₃·x³ < 0
nonlinear-table-escaped-3 = 模型不再能描述悬架
nonlinear-table-escaped-4 = 当 |x| 超过 1 m 时计算被截断

### uncertainty

uncertainty-quantity-zeta = 阻尼比 ζ
uncertainty-quantity-f0 = 固有频率 f0
uncertainty-quantity-q = 品质因数 Q
uncertainty-quantity-bandwidth = 半功率带宽
uncertainty-quantity-settling-time = 自由响应调节时间（±5 %）
uncertainty-hist-title = 蒙特卡罗：{ $quantity }
uncertainty-draws-provisional = { $draws }（{ $full } 计算中）
uncertainty-band-nominal-mass = 标称 m
uncertainty-band-lowest-corner = ζ 最小的角点
uncertainty-band-nominal = 标称
uncertainty-band-highest-corner = ζ 最大的角点
uncertainty-never = 永不
uncertainty-band-suspension = 从 { $start } 出发的自由响应，簧上质量分别为 +{ $percent } %、标称值和 −{ $percent } %
uncertainty-band-rlc = 电容电压从 1 V 出发，分别取容差盒中 ζ 最小的角点、标称值和 ζ 最大的角点
uncertainty-ignored-rlc = RLC 的滑块不起作用。
uncertainty-ignored-suspension = 悬架的滑块不起作用。
uncertainty-zeta-undefined = ζ 在范围的一端无定义
uncertainty-zeta-spans = ζ 的范围为 { $low }–{ $high }
uncertainty-describe-band = { $what }：{ $zeta }；5 % 调节时间（叉号）分别为 { $first }、{ $second } 和 { $third }。{ $ignored }
uncertainty-dist-normal = 正态（容差 = 3σ）
uncertainty-dist-uniform = 均匀
uncertainty-spec-zeta = 图中标出了 ζ 的规格窗口 { $low }–{ $high }；{ $share } 的抽样满足全部规格。
uncertainty-spec-settling-time = 图中标出了规格限值 { $limit }。
uncertainty-no-finite = 没有任何抽样得到有限的{ $quantity }。
uncertainty-describe-histogram = { $quantity }的直方图，共 { $draws } 次{ $distribution }抽样：从 { $low } 到 { $high }，第 5 百分位数 { $p5 }，第 95 百分位数 { $p95 }。
uncertainty-describe-histogram-spec = { $quantity }的直方图，共 { $draws } 次{ $distribution }抽样：从 { $low } 到 { $high }，第 5 百分位数 { $p5 }，第 95 百分位数 { $p95 }。{ $spec }
uncertainty-provisional-title = { $title }（临时）
uncertainty-provisional-description = 临时结果：基于前 { $shown } 次抽样，共 { $full } 次的计算仍在进行。{ $description }
uncertainty-axis-capacitor-voltage = 电容电压 v_C
uncertainty-settling-band = 5 % 调节带
uncertainty-axis-draws = 抽样数
uncertainty-series-bins = 每个区间的抽样数（{ $bins } 个区间）
uncertainty-no-finite-values = 没有有限值
uncertainty-spec-limit = 规格限值
uncertainty-percentiles = 第 5 / 95 百分位数
uncertainty-title = 容差分析
uncertainty-summary = 实际元件并不恰好等于其标称值。请选择系统：四分之一车辆（簧上质量 m、弹簧 k，阻尼器按标称质量下的 ζ 设定；车辆载重变化时质量在 ±dm 内变化）或串联 RLC 回路（R、L、C 分别在 ±dR、±dL、±dC 内）。只有所选系统的滑块起作用；另一组将被忽略。ζ、ωₙ 和 Q 的精确范围由容差盒的各角点得到。蒙特卡罗计算抽取 N 个设计（带随机种子，相同种子给出相同结果）：在容差内均匀分布，或以容差为 3σ 的正态分布。合格率是 ζ 落在规格窗口内、且 5 % 调节时间（从静止释放）不超过限值的抽样所占的比例。
uncertainty-param-system = 系统
uncertainty-param-system-suspension = 四分之一车辆悬架
uncertainty-param-system-rlc = 串联 RLC
uncertainty-param-m = 悬架：簧上质量
uncertainty-param-k = 悬架：弹簧刚度
uncertainty-param-zeta = 悬架：标称质量下的设计 ζ
uncertainty-param-dm = 悬架：质量容差 ±
uncertainty-param-R = RLC：电阻
uncertainty-param-L = RLC：电感
uncertainty-param-C = RLC：电容
uncertainty-param-dR = RLC：电阻容差 ±
uncertainty-param-dL = RLC：电感容差 ±
uncertainty-param-dC = RLC：电容容差 ±
uncertainty-param-dist = 元件分布
uncertainty-param-dist-uniform = 在 ±容差内均匀分布
uncertainty-param-dist-normal = 正态分布，容差 = 3σ
uncertainty-param-N = 蒙特卡罗抽样数
uncertainty-param-seed = 随机种子
uncertainty-param-zeta-lo = 规格：ζ 下限
uncertainty-param-zeta-hi = 规格：ζ 上限
uncertainty-param-ts-max = 规格：最长调节时间
uncertainty-param-hist = 第二个直方图
uncertainty-param-hist-zeta = 阻尼比 ζ
uncertainty-param-hist-f0 = 固有频率 f0
uncertainty-param-hist-q = 品质因数 Q
uncertainty-param-hist-bandwidth = 带宽
uncertainty-param-hist-settling-time = 调节时间
uncertainty-readout-zeta-min = ζ，最小值（精确）
uncertainty-readout-zeta-max = ζ，最大值（精确）
uncertainty-readout-wn-min = ωₙ，最小值（精确）
uncertainty-readout-wn-max = ωₙ，最大值（精确）
uncertainty-readout-Q-min = Q，最小值（精确）
uncertainty-readout-Q-max = Q，最大值（精确）
uncertainty-readout-yield = 合格率（满足规格）
uncertainty-readout-zeta-p5 = ζ，第 5 百分位数
uncertainty-readout-zeta-p95 = ζ，第 95 百分位数
uncertainty-readout-Q-p5 = Q，第 5 百分位数
uncertainty-readout-Q-p95 = Q，第 95 百分位数
uncertainty-readout-draws = 抽样数
uncertainty-readout-compute-time = 蒙特卡罗计算时间
uncertainty-plot-band = 容差范围内的自由响应带
uncertainty-plot-zeta-hist = 蒙特卡罗：阻尼比 ζ
uncertainty-plot-hist = 蒙特卡罗：所选物理量
uncertainty-preset-1 = ζ = 1 的设计，质量 ±10 %
uncertainty-preset-2 = ζ = 0.7 的设计，质量 ±10 %
uncertainty-preset-3 = RLC，元件精度 5 %
uncertainty-preset-4 = RLC，元件精度 20 %
