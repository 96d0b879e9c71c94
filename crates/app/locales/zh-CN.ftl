
### resonance

resonance-axis-ratio = 频率比 r = ω/ωₙ
resonance-axis-amplification = 放大系数 |H| = X/(F₀/k)
resonance-axis-magnitude-db = 幅值 20·log₁₀|H|
resonance-axis-phase = 相位 ∠H（x 滞后于 F）
resonance-plot-magnitude-db = 放大系数 |H(r)|（dB）
resonance-family = 曲线族 ζ = { $from } … { $to }
resonance-current = 当前 ζ = { $zeta }
resonance-drive = 驱动 r = { $ratio }
resonance-peak = 峰值
resonance-quadrature = r = 1 处 −90°
resonance-legend-width = 半功率宽度 r₂ − r₁ = { $width }
resonance-legend-broad = |H| ≥ |H|max/√2，直到 r = { $upper }
resonance-legend-cutoff = −3 dB 截止 r = { $upper }
resonance-band-width = 半功率点（|H| = |H|max/√2）位于 r = { $lower } 和 { $upper }：峰宽 r₂ − r₁ = { $width }
resonance-band-broad = 从 r = 0 到 r = { $upper }，|H| 始终高于 |H|max/√2：该峰没有下半功率点，因此其半功率宽度无定义
resonance-band-cutoff = |H| 在截止频率比 r = { $upper } 处降至静态值的 1/√2（−3 dB）；没有峰，也就没有半功率宽度
resonance-peak-at = 共振峰 { $gain }，位于 r = { $ratio }
resonance-no-peak = 没有共振峰（ζ ≥ 1/√2）：|H| 从 r = 0 处的 1 单调下降
resonance-describe-magnitude = { $view ->
        [db] ζ = { $zeta } 时的幅值（dB）：{ $peak }；{ $band }。在驱动频率比 r = { $drive } 处，放大系数为 { $gain }。
       *[linear] ζ = { $zeta } 时的幅值：{ $peak }；{ $band }。在驱动频率比 r = { $drive } 处，放大系数为 { $gain }。
    }
resonance-describe-phase = ζ = { $zeta } 时位移相对于力的相位滞后：低频时为 0°，对任何阻尼比在 r = 1 处均为 −90°，共振以上趋于 −180°；ζ 越小，转变越陡。在驱动频率比 r = { $drive } 处，滞后为 { $degrees }（{ $radians } rad）。
resonance-envelope = 包络线 ±E(t)
resonance-steady-amplitude = 稳态振幅 ±X
resonance-describe-time-growing = 从静止开始以 r = { $ratio }（ω = { $omega }）驱动 { $span }：没有稳态；振幅不断增大，达到 { $largest }。
resonance-describe-time = { $case ->
        [beats] 从静止开始以 r = { $ratio }（ω = { $omega }）驱动 { $span }：自由运动与受迫运动形成拍，拍周期为 { $period }（衰减时间常数 { $tau }），趋向稳态振幅 { $amplitude }，相位滞后于力 { $lag }。图中最大偏移为 { $largest }。
        [build-up] 从静止开始以 r = { $ratio }（ω = { $omega }）驱动 { $span }：在共振处振幅以时间常数 1/(ζωₙ) = { $tau } 逐渐增大，趋向稳态振幅 { $amplitude }，相位滞后于力 { $lag }。图中最大偏移为 { $largest }。
       *[transient] 从静止开始以 r = { $ratio }（ω = { $omega }）驱动 { $span }：经过瞬态过程（时间常数 { $tau }）后稳定在稳态振幅 { $amplitude }，相位滞后于力 { $lag }。图中最大偏移为 { $largest }。
    }
resonance-fixed-base = 固定基座
resonance-schematic = 固定基座上由弹簧和阻尼器支承的质量块，受力 F(t) = { $force } 推动（质量块上方的箭头），t = { $time }：偏离静止位置 { $displacement }。
resonance-beats-visible = 可见
resonance-beats-no-free-oscillation = 无（没有自由振荡，ζ ≥ 1）
resonance-beats-no-drive = 无（恒定力）
resonance-beats-same-frequency = 无（以 ω_d 驱动）
resonance-beats-too-fast = 无（与振荡一样快）
resonance-beats-dies-out = 无（自由运动先衰减消失）
resonance-title = 受迫共振
resonance-summary = 一个 1 kg 的质量块连接弹簧（k = ωₙ²·m）和阻尼器（c = 2ζωₙ·m），从静止开始，自 t = 0 起受力 F(t) = F₀·cos(ωt) 驱动。稳态时它以驱动频率运动，振幅为 |H(r)|·F₀/k，滞后于力的相角等于 H 的相位，其中 r = ω/ωₙ。轻阻尼在 r = 1 附近产生又高又窄的峰（高度 ≈ Q = 1/(2ζ)）。其半功率宽度，即 |H| = |H|max/√2 的两个频率比之间的 r₂ − r₁，在轻阻尼时 ≈ 2ζ；ζ ≈ 0.383 以上，下半功率点到达 r = 0，宽度无定义；ζ = 1/√2 以上则完全没有峰。恰好在共振处驱动时，振幅在几个时间常数 1/(ζωₙ) 内逐渐增大，不出现拍；在共振附近驱动时，自由运动与受迫运动相互形成拍，直到自由部分衰减消失。
resonance-param-zeta = 阻尼比
resonance-param-r = 激励频率比 ω/ωₙ
resonance-param-wn = 固有频率
resonance-param-F0 = 力幅值
resonance-param-view = 幅值显示方式
resonance-param-view-linear = 线性 |H|
resonance-param-view-db = 分贝 20·log₁₀|H|
resonance-readout-peak-gain = 共振峰 |H|max
resonance-readout-peak-ratio = 峰值位置 r = ω/ωₙ
resonance-readout-Q = 品质因数 Q = 1/(2ζ)
resonance-readout-peak-width = |H| 峰的半功率宽度 r₂ − r₁（ζ < 0.383）
resonance-readout-gain-at-r = 驱动处的增益 |H(r)|
resonance-readout-phase-at-r = 驱动处的相位 ∠H(r)
resonance-readout-amplitude = 稳态振幅 X = |H|·F₀/k
resonance-readout-beat-period = 拍周期 2π/|ω − ω_d|（出现拍时）
resonance-readout-beats = x(t) 中的拍
resonance-plot-magnitude = 放大系数 |H(r)|
resonance-plot-phase = 相位 ∠H(r)
resonance-plot-time = 从静止开始的响应 x(t)
resonance-preset-1 = 共振处，ζ = 0.05
resonance-preset-2 = 共振附近的拍，r = 0.9
resonance-preset-3 = 无峰，ζ ≈ 1/√2
resonance-preset-4 = 准静态，r = 0.2
resonance-preset-5 = 隔振，r = 3

### flutter

flutter-no-oscillation = 无振荡
flutter-series-h-section = 1940 年 H 形截面（教学近似）
flutter-series-box = 流线型箱梁（教学近似）
flutter-series-simplest = 最简模型等效的 A₂*
flutter-series-simplest-line = 最简模型 ζ_s − g·U
flutter-axis-reduced-velocity = 折减风速 U/(f·B) = 2π/K
flutter-axis-wind-speed = 风速 U
flutter-axis-effective-damping = 有效阻尼比 ζ_eff
flutter-axis-twist = 扭转角 θ
flutter-threshold = 阈值 4Iζ_s/(ρB⁴) = { $value }
flutter-upper-pole = 上极点
flutter-lower-pole = 下极点
flutter-amplitude = 振幅 ±a(t)
flutter-limit-cycle = 极限环 ±{ $amplitude }
flutter-describe-derivative = { $model ->
        [h] 1940 年 H 形截面
        [box] 流线型箱梁
       *[simplest] 最简模型
    }的 A₂* 随折减风速的变化（教学近似，并非实测值）：A₂* 超过 4Iζ_s/(ρB⁴) 时扭转增大。
flutter-describe-derivative-now = { $description }在 U = { $speed }（K = { $k }，U/(fB) = { $reduced_velocity }）时，A₂* = { $a2 }，{ $side ->
        [above] 高于
       *[below] 低于
    }阈值 { $threshold }。
flutter-describe-damping = { $model ->
        [h] 1940 年 H 形截面
        [box] 流线型箱梁
       *[simplest] 最简模型
    }的有效阻尼比，静风时从 ζ_s = { $zeta_s } 开始；{ $crossing ->
        [inside] 在临界风速 { $speed } 处过零
        [beyond] 只有在 { $speed } 才会过零，超出图中最大值 { $limit }
       *[never] 直到 100 m/s 都不过零：风只增加阻尼
    }。
flutter-describe-damping-now = { $description }在 U = { $speed } 时为 { $zeta }，{ $sign ->
        [positive] 为正（稳定）
        [negative] 为负（颤振）
       *[zero] 为零
    }。
flutter-describe-damping-still = { $description }在此风速下桥面不振荡。
flutter-describe-locus = 风速增大时的极点对：静风时为 { $re_calm } ± { $im_calm }i 1/s，在 { $limit } 时为 { $re_end } ± { $im_end }i 1/s，{ $crosses ->
        [yes] 在 U_crit 处穿过虚轴
       *[no] 始终不穿过虚轴
    }。
flutter-describe-locus-now = { $description }在 U = { $speed } 时，极点为 { $re } ± { $im }i 1/s，位于{ $side ->
        [right] 右半平面（不稳定）
       *[left] 左半平面（稳定）
    }。
flutter-oscillation = 振荡
flutter-oscillation-at = { $frequency } Hz 的振荡
flutter-describe-response = { $regime }：从初始扭转角 { $twist } 开始，{ $oscillation }{ $case ->
        [settling] 在图末（{ $window }）增大到 { $end }，接近 { $limit } 的极限环（{ $time } 后达到其 90%）
        [slow] 在图末（{ $window }）只增大到 { $end }；要达到 { $limit } 极限环的 90% 需要 { $time }
        [settled] 在图末（{ $window }）稳定在 { $limit } 的极限环上
        [grows] 在图末（{ $window }）增大到 { $end }
       *[dies] 在图末（{ $window }）衰减到 { $end }
    }。
flutter-describe-response-torn = { $description }如此大的扭转早已使任何桥面断裂；该界限只是一个教学假设。
flutter-schematic-title = 桥面截面
flutter-drawn-clipped = 绘图在 { $angle } 处截断
flutter-drawn-true-scale = 按真实比例绘制
flutter-drawn-larger = 放大 { $factor } 倍绘制
flutter-drawn-note = （{ $drawn }）
flutter-schematic = t = { $time } 时的桥面截面：扭转 { $twist }（{ $drawn }），风速 { $wind }，风从左侧吹来。
flutter-wind = 风速 U = { $speed }
flutter-title = 颤振：塔科马海峡大桥
flutter-summary = 稳定的风可以通过扭转桥面自身的运动向其输入能量。Scanlan 用风洞中测得的颤振导数描述风作用在扭转桥面上的力矩：A₂* 乘以扭转角速度（阻尼项），A₃* 乘以扭转角（刚度项），二者都是折减频率 K = Bω/U 的函数。桥面的阻尼比变为 ζ_eff ≈ ζ_s − ρB⁴A₂*(K)/(4I)：对于 1940 年塔科马桥面的钝体 H 形截面，A₂* 随风速增大而改变符号，一旦超过阈值 4Iζ_s/(ρB⁴)，任何微小扭转都会以桥面自身的扭转频率（约 0.2 Hz）增长——这是颤振，不是共振：稳定的风没有可以匹配的频率，运动自己产生激励。由于 K 依赖于频率，在每个风速下用迭代求频率。线性理论让扭转无限增长；这里假设风的阻尼项在扭转角 θ_s 时减半，从而把运动限制在一个大的极限环内，正如 1940 年 11 月 7 日那样：在约 42 mph 的风中，扭转在一小时内不断增大，直到桥面撕裂。教学近似，特此说明：A₂* 和 A₃* 是光滑曲线，形状仿照已发表的 H 形截面和类翼型截面结果（Scanlan 与 Tomko 1971；Billah 与 Scanlan 1991），并非从中读取的数值；I、ζ_s 和 θ_s 为假设值。流线型箱梁的 A₂* 始终为负，在此范围内从不发生颤振。保留最简模型 ζ_eff = ζ_s − g·U 以作比较。
flutter-param-U = 风速
flutter-param-model = 风致力矩模型
flutter-param-model-scanlan = 颤振导数（Scanlan）
flutter-param-model-linear = 最简模型：ζ_eff = ζ_s − g·U
flutter-param-section = 桥面截面
flutter-param-section-h = 1940 年 H 形截面（板梁）
flutter-param-section-box = 流线型箱梁
flutter-param-B = 桥面宽度
flutter-param-I = 单位长度质量惯性矩（1940 年的假设值）
flutter-param-f0 = 静风中的扭转频率
flutter-param-zeta-s = 结构阻尼比（1940 年的假设值）
flutter-param-theta0 = 初始扭转角
flutter-param-theta-s = 风的阻尼减半时的扭转角（教学假设）
flutter-param-slope = 最简模型：每 m/s 损失的阻尼
flutter-readout-regime = 小扭转的阻尼状态
flutter-readout-U-crit = 临界（颤振）风速 U_crit，搜索至 100 m/s
flutter-readout-zeta-eff = 小扭转的有效阻尼比 ζ_eff
flutter-readout-growth-rate = 小扭转的增长率 σ（< 0 为衰减）
flutter-readout-doubling-time = 小扭转的倍增时间
flutter-readout-frequency = 风中的扭转频率 f
flutter-readout-K = 折减频率 K = Bω/U
flutter-readout-reduced-velocity = 折减风速 U/(f·B) = 2π/K
flutter-readout-A2 = 颤振导数 A₂*(K)
flutter-readout-A3 = 颤振导数 A₃*(K)
flutter-readout-limit-deg = 极限环扭转振幅（采用假设界限 θ_s）
flutter-readout-time-to-large = 从 θ₀ 到极限环 90% 的时间
flutter-readout-amplitude-end-deg = 图末的扭转振幅
flutter-plot-derivative = 颤振导数 A₂* 与颤振阈值
flutter-plot-damping = 有效阻尼随风速的变化
flutter-plot-locus = 风速增大时的根轨迹
flutter-plot-response = 数分钟内的桥面扭转 θ(t)
flutter-preset-1 = 塔科马 1940，10 m/s（稳定）
flutter-preset-2 = 塔科马 1940，19 m/s（坍塌当天，≈ 42 mph）
flutter-preset-3 = 塔科马 1940，30 m/s 大风
flutter-preset-4 = 流线型箱梁桥面，19 m/s
flutter-preset-5 = 流线型箱梁桥面，40 m/s
flutter-preset-6 = 最简模型，19 m/s（ζ_eff = ζ_s − g·U）
flutter-table-caption = 颤振不是共振
flutter-table-column-1 = 情形
flutter-table-column-2 = 驱动因素
flutter-table-column-3 = 频率
flutter-table-column-4 = 阻尼
flutter-table-column-5 = 振幅
flutter-table-column-6 = 对策
flutter-table-resonance-1 = 受迫共振（作对比）
flutter-table-resonance-2 = 在 ωₙ 附近振荡的外力（齐步行进、发动机）
flutter-table-resonance-3 = 由外力决定；必须与 ωₙ 吻合
flutter-table-resonance-4 = 为正：将峰值限制在静态值的约 1/(2ζ) 倍
flutter-table-resonance-5 = 有界的稳态
flutter-table-resonance-6 = 调离共振，或增加阻尼
flutter-table-underdamped-1 = 风速低于 U_crit
flutter-table-underdamped-2 = 稳定的风；力矩 ∝ 扭转角速度（A₂*）和扭转角（A₃*）
flutter-table-underdamped-3 = 桥面自身的频率，被 A₃* 略微改变
flutter-table-underdamped-4 = ζ_eff > 0：A₂* 低于阈值 4Iζ_s/(ρB⁴)
flutter-table-underdamped-5 = 扭转逐渐消失
flutter-table-underdamped-6 = —
flutter-table-undamped-1 = 风速等于 U_crit
flutter-table-undamped-2 = 稳定的风；力矩 ∝ 扭转角速度（A₂*）和扭转角（A₃*）
flutter-table-undamped-3 = 桥面自身的频率
flutter-table-undamped-4 = ζ_eff = 0：极点位于虚轴上
flutter-table-undamped-5 = 扭转保持不变
flutter-table-undamped-6 = —
flutter-table-negatively-damped-1 = 颤振，风速高于 U_crit
flutter-table-negatively-damped-2 = 稳定的风；运动自己产生激励
flutter-table-negatively-damped-3 = 桥面自身的频率，无需匹配
flutter-table-negatively-damped-4 = ζ_eff < 0：每个周期都有能量输入
flutter-table-negatively-damped-5 = 不断增大，直到振幅界限（或桥面）失效
flutter-table-negatively-damped-6 = A₂* 始终为负的截面：流线型、开孔或加劲桥面
