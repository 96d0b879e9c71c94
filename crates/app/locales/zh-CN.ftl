### quarter-car

quarter-car-legend-comfort = 舒适 { $low }、{ $high }
quarter-car-legend-performance = 运动 { $low }、{ $high }
quarter-car-legend-critical = 临界 { $zeta }（×）
quarter-car-legend-overdamped = 过阻尼 { $zeta }（●）
quarter-car-group = { $group ->
        [comfort] 舒适
        [performance] 运动
        [critical] 临界
       *[overdamped] 过阻尼
    }
quarter-car-crossings = { $count ->
        [0] 不穿越平衡位置
        [1] 稳定前穿越平衡位置一次
       *[other] 稳定前穿越平衡位置 { $count } 次
    }
quarter-car-crossings-inside-band = 未穿越平衡位置即已稳定（其回弹留在误差带内）
quarter-car-settles-after = { $time } 后保持在静止位置附近 x₀ 的 ±{ $band } 以内
quarter-car-does-not-settle = 不能稳定
quarter-car-rebound = 最大回弹 { $rebound }（t = { $time }）
quarter-car-no-rebound = 无回弹
quarter-car-describe-design = 当前设计（ζ = { $zeta }，{ $regime }）：{ $crossings }，{ $settling }，{ $rebound }。
quarter-car-describe-undamped = 当前设计（ζ = 0，无阻尼）：以 { $frequency } 在 ±{ $amplitude } 之间永远振荡。
quarter-car-describe-unsettled = 当前设计（{ $regime }）：不能稳定。
quarter-car-list-separator = {"；"}
quarter-car-describe-response = { $design }本车上的各预设设定进入 x₀ 的 ±{ $band } 误差带：{ $family }。
quarter-car-member-settles = { $group } ζ = { $zeta } 用时 { $time }
quarter-car-member-unsettled = { $group } ζ = { $zeta } 不能稳定
quarter-car-two-sentences = { $first }{ $second }
quarter-car-settling-fastest = 本车自由响应进入 x₀ 的 ±{ $band } 误差带的调节时间随 ζ 的变化：ζ = { $zeta } 时最快（{ $time }），恰在一次跳变之后；每当一次回弹落入误差带内，调节时间就向下跳变。
quarter-car-settling-curve = 自由响应进入 x₀ 的 ±{ $band } 误差带的调节时间随 ζ 的变化。
quarter-car-settling-design = 当前设计 ζ = { $zeta }，调节时间为 { $time }。
quarter-car-settling-design-never = 当前设计 ζ = { $zeta }，永远不能稳定。
quarter-car-sensitivity-range = 簧上质量在 { $low } 到 { $high } 之间（±{ $variation }）且阻尼器和弹簧不变时，ζ 从 { $min } 变化到 { $max }（标称值 { $nominal }）；线性估计为 { $linear_min } 到 { $linear_max }。
quarter-car-sensitivity-undefined = 此设计的阻尼比范围无定义。
quarter-car-sensitivity-inside = 调节最快的 ζ = { $zeta } 位于此范围内：使 ζ 低于该值的载荷会使调节明显变慢。
quarter-car-sensitivity-outside = 调节最快的 ζ = { $zeta } 位于此范围之外。
quarter-car-schematic = 四分之一车辆，t = { $time }：车身{ $side ->
        [above] 高于
       *[below] 低于
    }静止位置 { $displacement }，路面固定。
quarter-car-settling-title = 进入 x₀ 的 ±{ $band } 误差带的调节时间随 ζ 的变化
quarter-car-axis-zeta = 阻尼比 ζ
quarter-car-axis-zeta-fastest = 阻尼比 ζ（虚线：最快 ζ = { $zeta }）
quarter-car-axis-settling-time = 调节时间 t_s
quarter-car-axis-sprung-mass = 簧上质量 m
quarter-car-fastest = 最快 ζ = { $zeta }
quarter-car-this-design = 当前设计
quarter-car-nominal = 标称值
quarter-car-road = 路面
quarter-car-band-label = x₀ 的 ±{ $band }
quarter-car-series-design = 当前设计，ζ { $zeta }
quarter-car-title = 四分之一车辆悬架
quarter-car-summary = 汽车的一个角：车身（簧上质量 m）支承在弹簧 k 和阻尼器 c 上，下方路面固定；车身被推离 x₀ 后从静止释放（x′(0) = 0）。c 和 ζ 是同一个阻尼器的两种表示，c = 2ζ√(km)：移动其中一个，另一个随之改变；改变 m 或 k 时阻尼器不变，因此 ζ 随之改变。细曲线是本车上的教科书式设定：舒适型（ζ ≈ 0.3–0.4）有回弹，运动型（ζ ≈ 0.65–0.7）稳定最快，临界（ζ = 1）和过阻尼设定无回弹地返回，但更慢。当 ζ 经过使某次回弹落入误差带内的数值时，调节时间发生跳变：最快的 ζ 恰好位于这样一次跳变之后，因此更重的载荷可能使调校良好的车越过这一边缘（见质量条带图）。调节以这一自由响应衡量：调节时间是 |x| 最后一次等于 误差带·|x₀| 的时刻，此后车身保持在静止位置的 ±误差带·|x₀| 以内（而不是阶跃响应终值附近的误差带）。
quarter-car-param-m = 簧上质量
quarter-car-param-k = 弹簧刚度
quarter-car-param-c = 阻尼器阻尼系数
quarter-car-param-zeta = 阻尼比
quarter-car-param-x0 = 初始位移
quarter-car-param-band = 静止位置附近的调节误差带（相对于 x₀）
quarter-car-param-dm = 簧上质量变化
quarter-car-readout-regime = 阻尼状态
quarter-car-readout-wn = 固有频率 ωₙ
quarter-car-readout-fn = 固有频率 fₙ
quarter-car-readout-zeta = 阻尼比 ζ
quarter-car-readout-c = 当前阻尼系数 c
quarter-car-readout-c-crit = 临界阻尼 2√(km)
quarter-car-readout-wd = 阻尼频率 ω_d
quarter-car-readout-settling-time = 进入 ±误差带·|x₀| 的调节时间 t_s（自由响应）
quarter-car-readout-overshoot = 最大回弹（相对于 x₀）
quarter-car-readout-peak-time = 最大回弹时刻
quarter-car-readout-zeta-argmin = 调节最快的 ζ（自由响应，相同误差带）
quarter-car-readout-settling-min = 其调节时间
quarter-car-readout-zeta-lo = 质量 +dm % 时的 ζ
quarter-car-readout-zeta-hi = 质量 −dm % 时的 ζ
quarter-car-plot-response = 车身位移 x(t)
quarter-car-plot-settling = 自由响应调节时间随 ζ 的变化
quarter-car-plot-sensitivity = 簧上质量变化时的 ζ
quarter-car-preset-1 = 舒适 ζ = 0.3
quarter-car-preset-2 = 舒适 ζ = 0.4
quarter-car-preset-3 = 运动 ζ = 0.65
quarter-car-preset-4 = 运动 ζ = 0.7
quarter-car-preset-5 = 临界 ζ = 1
quarter-car-preset-6 = 过阻尼 ζ = 2

### quarter-car-2dof

quarter-car-2dof-describe-motion = 经过{ $road ->
        [bump] 一个凸起
        [step] 一个台阶
        [sine] 正弦路面
       *[random] 随机路面
    }（最大路面高度 { $road_peak }），车身最大位移 { $body }（t = { $body_time }），车轮最大位移 { $wheel }（t = { $wheel_time }）。
quarter-car-2dof-describe-acceleration = 车身加速度峰值为 { $peak }（{ $peak_g } g）；在从静止开始的整个过程（0 到 { $window }）中，其均方根值为 { $rms }。
quarter-car-2dof-describe-tyre-lift-off = 轮胎变形（车轮高于路面，正值 = 轮胎卸载）范围为 { $low } 到 { $high }，均方根值 { $rms }；在 { $time } 首次达到静态变形 { $limit }，此时轮胎力降为零，车轮离开路面：离地 { $lift_offs } 次；离地时间 { $airborne }。
quarter-car-2dof-describe-tyre-contact = 轮胎变形（车轮高于路面，正值 = 轮胎卸载）范围为 { $low } 到 { $high }，均方根值 { $rms }；始终低于静态变形 { $limit }，因此轮胎保持接地。
quarter-car-2dof-describe-frf = 单位路面高度的频率响应，采用对数坐标。车身跟随缓慢的路面起伏（比值 1），在车身跳动频率 { $body_frequency } 附近达到峰值 { $body_peak }，更高频率处被隔离：20 Hz 时为 { $at_20 }。轮胎变形在车轮跳动频率 { $tyre_frequency } 附近达到峰值 { $tyre_peak }。
quarter-car-2dof-schematic = 四分之一车辆，t = { $time }：车身 { $body }，车轮 { $wheel }，路面 { $road }（按同一比例绘制）。
quarter-car-2dof-schematic-title = 示意图
quarter-car-2dof-axis-height = 相对平衡位置的高度
quarter-car-2dof-axis-acceleration = 加速度 z_s″
quarter-car-2dof-axis-tyre-deflection = 轮胎变形 z_u − u
quarter-car-2dof-axis-frequency = 频率 f
quarter-car-2dof-axis-magnitude = 单位路面高度的幅值
quarter-car-2dof-series-road = 路面 u
quarter-car-2dof-series-wheel = 车轮 z_u
quarter-car-2dof-series-body = 车身 z_s
quarter-car-2dof-series-body-acceleration = 车身加速度
quarter-car-2dof-series-rms = ± 均方根
quarter-car-2dof-series-lift-off = 离地界限（静态变形）
quarter-car-2dof-series-off-road = 车轮离地
quarter-car-2dof-series-body-gain = 车身/路面
quarter-car-2dof-series-tyre-gain = 轮胎变形/路面
quarter-car-2dof-marker-road = 路面
quarter-car-2dof-title = 含车身与车轮的四分之一车辆
quarter-car-2dof-summary = 两个质量，两个模态。车身（簧上质量 m_s）支承在悬架弹簧 k_s 和阻尼器 c_s 上；车轮（簧下质量 m_u）支承在轮胎弹簧 k_t 上，轮胎跟随路面 u(t)。车身跳动约在 1–1.5 Hz，是车身在较软悬架上的运动；车轮跳动约在 10–15 Hz，是较轻的车轮在刚硬的轮胎与悬架之间弹跳。频率响应同时显示两者：车身跟随缓慢的路面起伏，越过快速的起伏，在车身跳动附近振动最大；决定抓地力的轮胎变形在车轮跳动处达到峰值。轮胎只能推不能拉：当车轮升高超过其静态变形时，轮胎力为零，车轮离开路面，直到再次落地。舒适性以车身加速度均方根（RMS）衡量，抓地性以轮胎变形均方根衡量，两者都在从静止开始的整个过程 0 … T 内计算。在路面采样点之间响应是精确的，采样点足够密，可以跟上每个凸起和每次车轮跳动。位移从静平衡位置算起，向上为正；随机路面由 64 个正弦分量叠加而成，在 0.5–20 Hz 内符合 ISO 8608 谱。在随机路面上，页面还根据车辆的李雅普诺夫方程给出完整 ISO 8608 路面上的稳态车身加速度均方根，包括未加权值和按 ISO 2631-1 的 W_k 加权的值（a_w，舒适性指标）。
quarter-car-2dof-param-ms = 车身（簧上）质量
quarter-car-2dof-param-mu = 车轮（簧下）质量
quarter-car-2dof-param-ks = 悬架刚度
quarter-car-2dof-param-kt = 轮胎刚度
quarter-car-2dof-param-cs = 悬架阻尼
quarter-car-2dof-param-road = 路面输入
quarter-car-2dof-param-road-bump = 单个凸起（1 − cos）
quarter-car-2dof-param-road-step = 台阶（路缘）
quarter-car-2dof-param-road-sine = 正弦
quarter-car-2dof-param-road-random = 随机路面（ISO 8608）
quarter-car-2dof-param-h = 凸起或台阶高度、正弦幅值
quarter-car-2dof-param-L = 凸起长度
quarter-car-2dof-param-V = 车速
quarter-car-2dof-param-f-road = 正弦路面频率
quarter-car-2dof-param-class = 随机路面等级
quarter-car-2dof-param-class-A = A（很好）
quarter-car-2dof-param-class-B = B（好）
quarter-car-2dof-param-class-C = C（一般）
quarter-car-2dof-param-class-D = D（差）
quarter-car-2dof-param-class-E = E（很差）
quarter-car-2dof-param-class-F = F
quarter-car-2dof-param-class-G = G
quarter-car-2dof-param-class-H = H
quarter-car-2dof-param-seed = 随机路面种子
quarter-car-2dof-readout-f-body = 车身跳动频率 [Hz]
quarter-car-2dof-readout-f-wheel = 车轮跳动频率 [Hz]
quarter-car-2dof-readout-window = 均方根统计区间：从静止开始的整个过程，0 … T
quarter-car-2dof-readout-rms-body-accel = 0 … T 内车身加速度均方根（舒适性）
quarter-car-2dof-readout-rms-tyre-deflection = 0 … T 内轮胎变形 z_u − u 的均方根（抓地性）
quarter-car-2dof-readout-max-travel = 最大悬架行程 |z_s − z_u|
quarter-car-2dof-readout-static-tyre-deflection = 轮胎静态变形（超过即车轮离地）
quarter-car-2dof-readout-lift-off = 首次离地：轮胎力降为零
quarter-car-2dof-readout-airborne-time = 车轮离地时间
quarter-car-2dof-readout-rms-road = 路面高度均方根（随机路面）
quarter-car-2dof-readout-stationary-accel = 稳态车身加速度均方根，完整 ISO 8608 路面（随机路面）
quarter-car-2dof-readout-stationary-weighted-accel = 稳态 a_w：按 ISO 2631-1 W_k 加权的车身加速度均方根（随机路面）
quarter-car-2dof-readout-body-gain = 正弦频率下车身与路面的幅值比
quarter-car-2dof-readout-tyre-gain = 正弦频率下轮胎变形与路面幅值之比
quarter-car-2dof-plot-motion = 车身、车轮与路面
quarter-car-2dof-plot-accel = 车身加速度
quarter-car-2dof-plot-frf = 单位路面高度的频率响应
quarter-car-2dof-plot-tyre = 轮胎变形
quarter-car-2dof-preset-1 = 减速带 5 cm，10 m/s
quarter-car-2dof-preset-2 = 路缘台阶 5 cm
quarter-car-2dof-preset-3 = 车身跳动频率的路面波
quarter-car-2dof-preset-4 = 车轮跳动频率的路面波
quarter-car-2dof-preset-5 = 随机路面，C 级，20 m/s
quarter-car-2dof-preset-6 = 差路面上的软阻尼器

