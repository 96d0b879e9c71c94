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
