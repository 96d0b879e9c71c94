## Esquemas

schematic-title = Esquema
schematic-circuit = Circuito
### rlc

rlc-axis-current = corrente i
rlc-axis-voltage = tensão no capacitor v_C
rlc-envelope = envoltória
rlc-series-critical = R crítica = { $resistance }
rlc-schematic = Circuito RLC série em t = { $time }: corrente { $current }, capacitor em { $voltage }.
rlc-describe-current = { $regime ->
        [undamped] R = { $resistance }, não amortecido (um circuito LC sem perdas): a corrente oscila indefinidamente em ω₀ = { $frequency }, entre ±{ $bound } (toda a energia passa para o indutor e volta a cada meio período).
        [underdamped] R = { $resistance }, abaixo da resistência crítica { $critical }, subamortecido: a corrente oscila em ω_d = { $ringing } (Q = { $q }), decaindo como e^(−αt) com α = { $alpha }; nunca ultrapassa { $bound }.
        [critical] R = { $resistance }, igual à resistência crítica, criticamente amortecido: um único pulso de corrente (negativo, com o capacitor se descarregando) que volta a zero sem inverter; a corrente nunca ultrapassa { $bound }.
       *[overdamped] R = { $resistance }, acima da resistência crítica { $critical }, superamortecido: um pulso lento de corrente (negativo, com o capacitor se descarregando) sem inverter, constante de tempo lenta { $time }.
    }
rlc-describe-voltage = { $regime ->
        [undamped] R = { $resistance }, não amortecido (um circuito LC sem perdas): a tensão no capacitor oscila indefinidamente entre +{ $voltage } e −{ $voltage } em ω₀ = { $frequency }.
        [underdamped] R = { $resistance }, abaixo da resistência crítica { $critical }, subamortecido: a tensão no capacitor { $reversal ->
            [slight] se inverte apenas levemente (no máximo { $rebound } de V₀, dentro da faixa)
            [count] { $crossings ->
                [one] inverte a polaridade uma vez antes de se acomodar
               *[other] inverte a polaridade { $crossings } vezes antes de se acomodar
            }
           *[never] nunca inverte a polaridade
        } e { $settles ->
            [yes] fica dentro de 5 % de V₀ após { $time }
           *[no] nunca se acomoda
        }.
        [critical] R = { $resistance }, igual à resistência crítica, criticamente amortecido: o capacitor se descarrega o mais rápido possível sem inverter; a tensão { $settles ->
            [yes] fica dentro de 5 % de V₀ após { $time }
           *[no] nunca se acomoda
        }.
       *[overdamped] R = { $resistance }, acima da resistência crítica { $critical }, superamortecido: o capacitor se descarrega lentamente sem inverter; a tensão { $settles ->
            [yes] fica dentro de 5 % de V₀ após { $time }
           *[no] nunca se acomoda
        }.
    }
rlc-title = Circuito RLC série
rlc-summary = Um capacitor carregado com V₀ é ligado em t = 0 a uma malha com um indutor e um resistor. A carga q obedece à mesma equação de uma massa presa a uma mola: L faz o papel da massa, R o do amortecedor e 1/C o da mola. Com R abaixo da resistência crítica 2√(L/C), a energia vai e volta entre C e L e a corrente oscila em ω_d, decaindo como e^(−αt), α = R/(2L); com R = 2√(L/C), o capacitor se descarrega o mais rápido possível sem inverter; acima disso, a descarga volta a ser mais lenta. Q = 1/(2ζ) mede o quanto o circuito oscila, e R/L é a largura de banda de meia potência da ressonância da corrente: sob uma tensão senoidal, |I|² fica acima da metade do seu pico numa faixa de exatamente R/L rad/s, para qualquer R. A corrente é negativa enquanto o capacitor se descarrega (i = dq/dt).
rlc-param-R = resistência
rlc-param-L = indutância
rlc-param-C = capacitância
rlc-param-V0 = tensão inicial no capacitor
rlc-readout-regime = regime
rlc-readout-w0 = frequência de ressonância ω₀ = 1/√(LC)
rlc-readout-f0 = frequência de ressonância f₀
rlc-readout-alpha = taxa de decaimento α = R/(2L)
rlc-readout-zeta = razão de amortecimento ζ
rlc-readout-Q = fator de qualidade Q = 1/(2ζ)
rlc-readout-bandwidth = largura de banda de meia potência da ressonância da corrente Δω = R/L
rlc-readout-R-crit = resistência crítica 2√(L/C)
rlc-readout-wd = frequência de oscilação ω_d
rlc-readout-settling-time = v_C dentro de 5 % de V₀ após
rlc-plot-current = Corrente i(t)
rlc-plot-voltage = Tensão no capacitor v_C(t)
rlc-preset-1 = LC sem perdas, R = 0
rlc-preset-2 = Oscilante, R = 2 Ω
rlc-preset-3 = Subamortecido, R = 5 Ω
rlc-preset-4 = Crítico, R = 10 Ω
rlc-preset-5 = Superamortecido, R = 20 Ω

### analogy

analogy-axis-response = resposta normalizada
analogy-axis-energy = energia
analogy-series-x = x/x₀ massa
analogy-series-q = q/q₀ circuito
analogy-series-v = v/(x₀ωₙ) massa
analogy-series-i = i/(q₀ω₀) circuito
analogy-series-spring = ½kx² mola
analogy-series-capacitor = ½q²/C capacitor
analogy-series-mass = ½mv² massa
analogy-series-inductor = ½Li² indutor
analogy-series-total-mass = total, massa
analogy-series-total-circuit = total, circuito
analogy-caption-mechanical = mecânico
analogy-caption-electrical = elétrico
analogy-schematic-title = Gêmeos mecânico e elétrico
analogy-describe-responses = { $regime } (ζ = { $zeta }): o x/x₀ mecânico e o q/q₀ elétrico coincidem, assim como a velocidade v/(x₀ωₙ) e a corrente i/(q₀ω₀) ({ $same ->
        [exact] idênticos até o último dígito
       *[close] diferença máxima de { $difference }
    }); { $motion ->
        [decaying] ambos oscilam em ω_d = { $frequency } e decaem com constante de tempo 1/(ζωₙ) = { $time }
        [lasting] ambos oscilam indefinidamente em ω₀ = ωₙ = { $frequency }
       *[creeping] ambos voltam lentamente ao repouso sem oscilar
    }.
analogy-describe-energy = Em t = 0, toda a energia, { $energy }, está armazenada na mola e, igualmente, no capacitor. { $exchange ->
        [swings] Ela passa para a massa (indutor), no máximo { $peak } de cada vez, e volta, duas vezes por ciclo
       *[passes] Sem oscilar, no máximo { $peak } passa pela massa (indutor)
    }; { $loss ->
        [none] sem amortecedor (resistor), ela continua toda lá após { $time }
       *[heat] o amortecedor c (resistor R) a transforma em calor, restando { $left } ({ $percent }) após { $time }
    }. As curvas mecânica e elétrica coincidem.
analogy-schematic = Em t = { $time }: a massa está deslocada { $displacement } e se move a { $velocity }; o capacitor armazena { $charge } e a corrente é { $current }. Os mesmos números em unidades diferentes.
analogy-title = Uma equação, duas máquinas
analogy-summary = Uma massa presa a uma mola e a um amortecedor e uma malha série indutor–resistor–capacitor obedecem à mesma equação de segunda ordem. Na analogia força–tensão, massa m ↔ indutância L, amortecimento c ↔ resistência R, rigidez k ↔ 1/C, força F ↔ tensão E e deslocamento x ↔ carga q (logo, velocidade ↔ corrente). Aqui o circuito recebe os mesmos números que o mecanismo (L em H = m em kg, R em Ω = c em N·s/m, 1/C em 1/F = k em N/m, q₀ em C = x₀ em m), e ambos partem do repouso: mova qualquer controle deslizante e as duas máquinas mudam juntas, suas respostas normalizadas continuam sendo uma única curva, e a energia vai e volta entre a mola e a massa exatamente como entre o capacitor e o indutor.
analogy-param-m = massa (≙ indutância L)
analogy-param-c = amortecimento (≙ resistência R)
analogy-param-k = rigidez da mola (≙ 1/C)
analogy-param-x0 = deslocamento inicial (≙ carga q₀)
analogy-readout-m = massa m
analogy-readout-L = indutância L (≙ massa m)
analogy-readout-c = amortecimento c
analogy-readout-R = resistência R (≙ amortecimento c)
analogy-readout-k = rigidez da mola k
analogy-readout-elastance = elastância 1/C (≙ k)
analogy-readout-compliance = flexibilidade 1/k (≙ C)
analogy-readout-C = capacitância C (≙ 1/k)
analogy-readout-x0 = deslocamento inicial x₀
analogy-readout-q0 = carga inicial q₀ (≙ x₀)
analogy-readout-wn = frequência natural ωₙ = √(k/m)
analogy-readout-w0 = frequência de ressonância ω₀ = 1/√(LC) (≙ ωₙ)
analogy-readout-zeta = razão de amortecimento ζ (ambos)
analogy-readout-regime = regime (ambos)
analogy-readout-Q = fator de qualidade Q (ambos)
analogy-readout-energy = energia armazenada ½kx₀² = ½q₀²/C
analogy-plot-responses = Respostas normalizadas das duas máquinas
analogy-plot-energy = Troca de energia
analogy-preset-1 = Mola sem atrito ↔ circuito tanque LC (c = R = 0)
analogy-preset-2 = Amortecimento leve ζ = 0,05
analogy-preset-3 = Crítico ζ = 1 (c = 2√(mk), R = 2√(L/C))
analogy-preset-4 = Superamortecido ζ = 2
analogy-preset-5 = Pesado e macio: m = 4 kg ↔ L = 4 H, k = 25 N/m ↔ C = 40 mF
analogy-table-caption = A analogia força–tensão: a·y″ + b·y′ + c·y = f(t) lida de duas maneiras, com os valores atuais das duas máquinas
analogy-table-column-1 = papel na equação
analogy-table-column-2 = mecânico
analogy-table-column-3 = valor atual
analogy-table-column-4 = elétrico
analogy-table-column-5 = valor atual
analogy-table-inertia-1 = inércia a
analogy-table-inertia-2 = massa m [kg]
analogy-table-inertia-4 = indutância L [H]
analogy-table-dissipation-1 = dissipação b
analogy-table-dissipation-2 = coeficiente de amortecimento c [N·s/m]
analogy-table-dissipation-4 = resistência R [Ω]
analogy-table-stiffness-1 = rigidez c
analogy-table-stiffness-2 = rigidez da mola k [N/m]
analogy-table-stiffness-4 = elastância 1/C [1/F]
analogy-table-compliance-1 = flexibilidade 1/c
analogy-table-compliance-2 = flexibilidade 1/k [m/N]
analogy-table-compliance-4 = capacitância C [F]
analogy-table-drive-1 = excitação f(t)
analogy-table-drive-2 = força F [N]
analogy-table-drive-3 = 0: parte do repouso
analogy-table-drive-4 = tensão E [V]
analogy-table-drive-5 = 0: sem fonte na malha
analogy-table-coordinate-1 = coordenada y, inicialmente y₀
analogy-table-coordinate-2 = deslocamento x, inicialmente x₀ [m]
analogy-table-coordinate-4 = carga q, inicialmente q₀ [C]
analogy-table-rate-1 = derivada y′
analogy-table-rate-2 = velocidade v = ẋ [m/s]
analogy-table-rate-3 = 0 ao soltar
analogy-table-rate-4 = corrente i = q̇ [A]
analogy-table-rate-5 = 0 ao soltar
analogy-table-natural-frequency-1 = frequência natural √(c/a)
analogy-table-natural-frequency-2 = ωₙ = √(k/m) [rad/s]
analogy-table-natural-frequency-4 = ω₀ = 1/√(LC) [rad/s]
analogy-table-damping-ratio-1 = razão de amortecimento ζ = b/(2√(ac))
analogy-table-damping-ratio-2 = ζ = c/(2√(mk))
analogy-table-damping-ratio-4 = ζ = (R/2)·√(C/L)
analogy-table-quality-factor-1 = fator de qualidade Q = √(ac)/b
analogy-table-quality-factor-2 = Q = √(mk)/c
analogy-table-quality-factor-4 = Q = √(L/C)/R
analogy-table-potential-energy-1 = armazenada pela rigidez
analogy-table-potential-energy-2 = mola ½kx², ao soltar ½kx₀² [J]
analogy-table-potential-energy-4 = capacitor ½q²/C, ao soltar ½q₀²/C [J]
analogy-table-kinetic-energy-1 = armazenada pela inércia
analogy-table-kinetic-energy-2 = massa ½mv² [J]
analogy-table-kinetic-energy-3 = 0 ao soltar
analogy-table-kinetic-energy-4 = indutor ½Li² [J]
analogy-table-kinetic-energy-5 = 0 ao soltar
analogy-table-power-lost-1 = potência dissipada
analogy-table-power-lost-2 = amortecedor c·v² [W]
analogy-table-power-lost-3 = 0 ao soltar
analogy-table-power-lost-4 = resistor R·i² [W]
analogy-table-power-lost-5 = 0 ao soltar

### universality

universality-axis-response = resposta normalizada y/y₀
universality-axis-time = tempo normalizado ωₙt
universality-series-critical = ζ = 1 (crítico), como referência
universality-schematic-title = Máquinas A e B
universality-match-off = desligado
universality-match-on = ligado: B tem os mesmos ωₙ e ζ de A
universality-match-too-light = inalcançável: mantidos os seus outros parâmetros, B não consegue ficar abaixo de ζ = { $zeta_min }; A tem ζ = { $zeta }
universality-match-out-of-range = inalcançável dentro dos controles: B precisaria de { $symbol } = { $value }, fora de { $low } … { $high }
universality-match-impossible = inalcançável: A não tem frequência natural
universality-describe-normalised = Liberadas a partir do repouso: A ({ $machine_a }, ζ = { $zeta_a }) { $behaviour_a ->
        [forever] oscila indefinidamente
        [dies-away] oscila e se extingue
        [fastest] volta o mais rápido possível sem sobressinal
       *[creeps] volta lentamente sem sobressinal
    }; B ({ $machine_b }, ζ = { $zeta_b }) { $behaviour_b ->
        [forever] oscila indefinidamente
        [dies-away] oscila e se extingue
        [fastest] volta o mais rápido possível sem sobressinal
       *[creeps] volta lentamente sem sobressinal
    }. { $relation ->
        [coincide] As duas curvas coincidem (diferença máxima de { $gap }).
       *[differ] As curvas diferem em até { $gap } de y₀.
    }{ $thermal ->
        [yes] { " " }Um sistema térmico de duas capacidades não pode oscilar: seu ζ fica acima de 1 para quaisquer capacidades e resistências.
       *[no] { "" }
    }
universality-describe-realtime = Tempo real ao longo de { $window }: escala de tempo 1/ωₙ de A { $scale_a }, de B { $scale_b }; { $pace ->
        [faster] B é { $factor } vezes mais rápida que A
        [slower] B é { $factor } vezes mais lenta que A
       *[same] B acompanha A exatamente
    }.
universality-schematic = Em t = { $time }: A, { $machine_a }: { $coordinate_a } = { $value_a }; B, { $machine_b }: { $coordinate_b } = { $value_b }.
universality-title = Uma equação, muitas máquinas
universality-summary = Seis máquinas, uma equação a·y″ + b·y′ + c·y = f(t). Escolha uma máquina para A e outra para B e ajuste cada uma pelos seus próprios parâmetros físicos: cada uma fornece seus próprios a, b e c, em suas próprias unidades, e daí uma frequência natural ωₙ = √(c/a) e uma razão de amortecimento ζ = b/(2√(ac)). Liberada a partir de y₀ em repouso, a resposta normalizada y/y₀ de uma máquina em função de ωₙt depende apenas de ζ, de modo que máquinas com o mesmo ζ traçam uma única curva. Marque “igualar” e os parâmetros de ajuste de B são calculados para que seus ωₙ e ζ sejam iguais aos de A: então B se comporta exatamente como A, segundo a segundo. O sistema térmico de duas capacidades nunca oscila: b² − 4ac = (τ₁ − τ₂)² + R₁C₂(2τ₁ + 2τ₂ + R₁C₂) > 0, logo seu ζ > 1 quaisquer que sejam suas capacidades e resistências — o calor não tem inércia que o leve além do equilíbrio.
universality-param-A = máquina A
universality-param-A-mass-spring = massa–mola–amortecedor
universality-param-A-rlc = circuito RLC série
universality-param-A-u-tube = manômetro de tubo em U
universality-param-A-servo = servo de posição com motor CC (controle PD)
universality-param-A-storey = andar de edifício sob movimento do solo
universality-param-A-thermal = sistema térmico de duas capacidades
universality-param-A-m = massa
universality-param-A-c = coeficiente de amortecimento
universality-param-A-k = rigidez da mola
universality-param-A-L = indutância
universality-param-A-R = resistência
universality-param-A-C = capacitância
universality-param-A-len = comprimento da coluna de líquido
universality-param-A-bore = diâmetro interno do tubo
universality-param-A-rho = massa específica do líquido
universality-param-A-mu = viscosidade dinâmica
universality-param-A-J = inércia do motor e da carga
universality-param-A-Kt = constante de torque do motor
universality-param-A-Ra = resistência de armadura
universality-param-A-Kp = ganho proporcional
universality-param-A-Kd = ganho derivativo
universality-param-A-mf = massa do piso
universality-param-A-h = altura do andar
universality-param-A-EI = rigidez à flexão de cada um dos 4 pilares
universality-param-A-cf = coeficiente de amortecimento do andar
universality-param-A-C1 = capacidade térmica do corpo 1
universality-param-A-R1 = resistência térmica, do corpo 1 ao ambiente
universality-param-A-C2 = capacidade térmica do corpo 2
universality-param-A-R2 = resistência térmica, do corpo 2 ao corpo 1
universality-param-B = máquina B
universality-param-B-mass-spring = massa–mola–amortecedor
universality-param-B-rlc = circuito RLC série
universality-param-B-u-tube = manômetro de tubo em U
universality-param-B-servo = servo de posição com motor CC (controle PD)
universality-param-B-storey = andar de edifício sob movimento do solo
universality-param-B-thermal = sistema térmico de duas capacidades
universality-param-B-m = massa
universality-param-B-c = coeficiente de amortecimento
universality-param-B-k = rigidez da mola
universality-param-B-L = indutância
universality-param-B-R = resistência
universality-param-B-C = capacitância
universality-param-B-len = comprimento da coluna de líquido
universality-param-B-bore = diâmetro interno do tubo
universality-param-B-rho = massa específica do líquido
universality-param-B-mu = viscosidade dinâmica
universality-param-B-J = inércia do motor e da carga
universality-param-B-Kt = constante de torque do motor
universality-param-B-Ra = resistência de armadura
universality-param-B-Kp = ganho proporcional
universality-param-B-Kd = ganho derivativo
universality-param-B-mf = massa do piso
universality-param-B-h = altura do andar
universality-param-B-EI = rigidez à flexão de cada um dos 4 pilares
universality-param-B-cf = coeficiente de amortecimento do andar
universality-param-B-C1 = capacidade térmica do corpo 1
universality-param-B-R1 = resistência térmica, do corpo 1 ao ambiente
universality-param-B-C2 = capacidade térmica do corpo 2
universality-param-B-R2 = resistência térmica, do corpo 2 ao corpo 1
universality-param-match = igualar: ajustar B para se comportar como A (mesmos ωₙ e ζ)
universality-readout-a-A = coeficiente de inércia a de A
universality-readout-b-A = coeficiente de amortecimento b de A
universality-readout-c-A = coeficiente de rigidez c de A
universality-readout-wn-A = frequência natural ωₙ de A
universality-readout-zeta-A = razão de amortecimento ζ de A
universality-readout-regime-A = regime de A
universality-readout-a-B = coeficiente de inércia a de B
universality-readout-b-B = coeficiente de amortecimento b de B
universality-readout-c-B = coeficiente de rigidez c de B
universality-readout-wn-B = frequência natural ωₙ de B
universality-readout-zeta-B = razão de amortecimento ζ de B
universality-readout-regime-B = regime de B
universality-readout-wn-ratio = razão das escalas de tempo ωₙ(B)/ωₙ(A)
universality-readout-match = igualação
universality-plot-normalised = Respostas normalizadas y/y₀ em função de ωₙt
universality-plot-realtime = Respostas em tempo real
universality-preset-1 = Massa–mola e circuito RLC, igualados
universality-preset-2 = Manômetro de tubo em U e massa–mola, igualados
universality-preset-3 = Andar de edifício ajustado como um servo
universality-preset-4 = Termômetro (duas capacidades) e massa–mola, igualados
universality-preset-5 = Um sistema térmico não consegue igualar um oscilador
universality-table-caption = Uma equação, muitas máquinas: o que são y, a, b e c
universality-table-column-1 = máquina
universality-table-column-2 = coordenada y
universality-table-column-3 = a
universality-table-column-4 = b
universality-table-column-5 = c
universality-table-column-6 = ωₙ
universality-table-column-7 = ζ
universality-table-mass-spring-1 = massa–mola–amortecedor
universality-table-mass-spring-2 = deslocamento x [m]
universality-table-mass-spring-3 = massa m [kg]
universality-table-mass-spring-4 = coeficiente de amortecimento c [N·s/m]
universality-table-mass-spring-5 = rigidez da mola k [N/m]
universality-table-mass-spring-6 = √(k/m)
universality-table-mass-spring-7 = c/(2√(km))
universality-table-rlc-1 = circuito RLC série
universality-table-rlc-2 = carga q [C]
universality-table-rlc-3 = indutância L [H]
universality-table-rlc-4 = resistência R [Ω]
universality-table-rlc-5 = 1/C [1/F]
universality-table-rlc-6 = 1/√(LC)
universality-table-rlc-7 = (R/2)·√(C/L)
universality-table-u-tube-1 = manômetro de tubo em U
universality-table-u-tube-2 = variação de nível h [m]
universality-table-u-tube-3 = ρAL [kg]
universality-table-u-tube-4 = 8πμL [N·s/m]
universality-table-u-tube-5 = 2ρgA [N/m]
universality-table-u-tube-6 = √(2g/L)
universality-table-u-tube-7 = 16μ/(ρd²ωₙ)
universality-table-servo-1 = servo de posição com motor CC (controle PD)
universality-table-servo-2 = erro de ângulo θ [rad]
universality-table-servo-3 = J [kg·m²]
universality-table-servo-4 = K_t(K_t + K_d)/R_a [N·m·s/rad]
universality-table-servo-5 = K_t·K_p/R_a [N·m/rad]
universality-table-servo-6 = √(K_t·K_p/(R_a·J))
universality-table-servo-7 = ≥ K_t²/(2ωₙR_a·J), só pela força contraeletromotriz
universality-table-storey-1 = andar de edifício sob movimento do solo
universality-table-storey-2 = deslocamento relativo do andar u [m]
universality-table-storey-3 = massa do piso m [kg]
universality-table-storey-4 = coeficiente de amortecimento c [N·s/m]
universality-table-storey-5 = 12·4·EI/h³ [N/m]
universality-table-storey-6 = √(48EI/(m·h³))
universality-table-storey-7 = c/(2√(km))
universality-table-thermal-1 = sistema térmico de duas capacidades
universality-table-thermal-2 = excesso de temperatura T₂ [K]
universality-table-thermal-3 = R₁C₁R₂C₂ [s²]
universality-table-thermal-4 = R₁C₁ + R₂C₂ + R₁C₂ [s]
universality-table-thermal-5 = 1
universality-table-thermal-6 = 1/√(τ₁τ₂)
universality-table-thermal-7 = (τ₁ + τ₂ + R₁C₂)/(2√(τ₁τ₂)) > 1

### regimes

regimes-envelope = envoltória ±A·e^(−ζωₙt)
regimes-series-response = x(t), { $regime }
regimes-describe-settles = { $regime }: { $swings ->
        [0] não cruza o equilíbrio antes de se acomodar
        [one] cruza o equilíbrio uma vez antes de se acomodar
       *[other] cruza o equilíbrio { $swings } vezes antes de se acomodar
    }, fica dentro de 5 % do repouso após { $time }, ressalto máximo { $rebound }.
regimes-describe-unsettled = { $regime }: { $swings ->
        [0] não cruza o equilíbrio antes de se acomodar
        [one] cruza o equilíbrio uma vez antes de se acomodar
       *[other] cruza o equilíbrio { $swings } vezes antes de se acomodar
    }, não se acomoda, ressalto máximo { $rebound }.
regimes-describe-undamped = não amortecido: oscila indefinidamente com amplitude { $amplitude } em { $frequency }.
regimes-describe-growing = amortecimento negativo: a resposta cresce sem limite, por um fator e a cada { $time }.
regimes-describe-at-rest = { $regime }: parte do repouso no equilíbrio.
regimes-poles = Polos em { $re1 } { $sign1 } { $im1 }i e { $re2 } { $sign2 } { $im2 }i 1/s, no semiplano { $side ->
        [right] direito (instável)
       *[left] esquerdo (estável)
    }.
regimes-schematic = Massa sobre mola e amortecedor em t = { $time }: deslocada { $displacement } do repouso.
regimes-title = Regimes de amortecimento
regimes-summary = Resposta livre a partir de x(0) = x₀, x′(0) = v₀. A razão de amortecimento ζ define o regime: ζ = 0 não amortecido, 0 < ζ < 1 subamortecido, ζ = 1 criticamente amortecido, ζ > 1 superamortecido, ζ < 0 amortecimento negativo (a resposta cresce). Os polos s = −ζωₙ ± ωₙ√(ζ² − 1) percorrem um círculo de raio ωₙ, chegam ao eixo real em ζ = 1 e cruzam o eixo imaginário em ζ = 0.
regimes-param-wn = frequência natural
regimes-param-zeta = razão de amortecimento
regimes-param-x0 = deslocamento inicial
regimes-param-v0 = velocidade inicial
regimes-readout-regime = regime
regimes-readout-wn = frequência natural ωₙ
regimes-readout-zeta = razão de amortecimento ζ
regimes-readout-wd = frequência amortecida ω_d
regimes-readout-pole-re = parte real do polo
regimes-readout-pole-im = parte imaginária do polo
regimes-plot-response = Resposta livre x(t)
regimes-plot-poles = Polos no plano s
regimes-preset-1 = Não amortecido ζ = 0
regimes-preset-2 = Subamortecido ζ = 0,2
regimes-preset-3 = Criticamente amortecido ζ = 1
regimes-preset-4 = Superamortecido ζ = 2
regimes-preset-5 = Amortecimento negativo ζ = −0,1
regimes-table-caption = Os regimes de amortecimento
regimes-table-column-1 = regime
regimes-table-column-2 = condição
regimes-table-column-3 = raízes s₁, s₂
regimes-table-column-4 = comportamento
regimes-table-column-5 = exemplos de engenharia
regimes-table-undamped-1 = Não amortecido
regimes-table-undamped-2 = ζ = 0
regimes-table-undamped-3 = ±iωₙ, no eixo imaginário
regimes-table-undamped-4 = oscila indefinidamente em ωₙ
regimes-table-undamped-5 = pêndulo ideal, circuito tanque LC
regimes-table-underdamped-1 = Subamortecido
regimes-table-underdamped-2 = 0 < ζ < 1
regimes-table-underdamped-3 = −ζωₙ ± iω_d, par complexo
regimes-table-underdamped-4 = oscilação decrescente em ω_d
regimes-table-underdamped-5 = suspensão de automóvel (ζ ≈ 0,2–0,7), corda de violão
regimes-table-critically-damped-1 = Criticamente amortecido
regimes-table-critically-damped-2 = ζ = 1
regimes-table-critically-damped-3 = −ωₙ, raiz real dupla
regimes-table-critically-damped-4 = retorno mais rápido sem oscilar
regimes-table-critically-damped-5 = mola aérea de porta, ponteiro de medidor analógico
regimes-table-overdamped-1 = Superamortecido
regimes-table-overdamped-2 = ζ > 1
regimes-table-overdamped-3 = duas raízes reais negativas
regimes-table-overdamped-4 = retorno lento, sem oscilação
regimes-table-overdamped-5 = amortecedor hidráulico pesado, termômetro
regimes-table-negatively-damped-1 = Amortecimento negativo
regimes-table-negatively-damped-2 = ζ < 0
regimes-table-negatively-damped-3 = semiplano direito
regimes-table-negatively-damped-4 = oscilação crescente
regimes-table-negatively-damped-5 = flutter (ponte de Tacoma Narrows), freios que chiam
### quarter-car

quarter-car-legend-comfort = conforto { $low } e { $high }
quarter-car-legend-performance = esportivo { $low } e { $high }
quarter-car-legend-critical = crítico { $zeta } (×)
quarter-car-legend-overdamped = superamortecido { $zeta } (●)
quarter-car-group = { $group ->
        [comfort] conforto
        [performance] esportivo
        [critical] crítico
       *[overdamped] superamortecido
    }
quarter-car-crossings = { $count ->
        [0] não cruza o equilíbrio
        [one] cruza o equilíbrio uma vez antes de se acomodar
       *[other] cruza o equilíbrio { $count } vezes antes de se acomodar
    }
quarter-car-crossings-inside-band = acomoda-se antes de cruzar o equilíbrio (seu ressalto fica dentro da faixa)
quarter-car-settles-after = fica dentro de ±{ $band } de x₀ em torno do repouso após { $time }
quarter-car-does-not-settle = não se acomoda
quarter-car-rebound = ressalto máximo de { $rebound } em { $time }
quarter-car-no-rebound = sem ressalto
quarter-car-describe-design = Este ajuste (ζ = { $zeta }, { $regime }): { $crossings }, { $settling }, { $rebound }.
quarter-car-describe-undamped = Este ajuste (ζ = 0, não amortecido): oscila indefinidamente entre ±{ $amplitude } a { $frequency }.
quarter-car-describe-unsettled = Este ajuste ({ $regime }): não se acomoda.
quarter-car-list-separator = {"; "}
quarter-car-describe-response = { $design } Ajustes de referência neste carro, com acomodação em ±{ $band } de x₀: { $family }.
quarter-car-member-settles = { $group } ζ = { $zeta } em { $time }
quarter-car-member-unsettled = { $group } ζ = { $zeta } não se acomoda
quarter-car-two-sentences = { $first } { $second }
quarter-car-settling-fastest = Tempo de acomodação da resposta livre em ±{ $band } de x₀ em função de ζ para este carro: o mais rápido é ζ = { $zeta } ({ $time }), logo após um salto; ele cai bruscamente cada vez que um ressalto passa para dentro da faixa.
quarter-car-settling-curve = Tempo de acomodação da resposta livre em ±{ $band } de x₀ em função de ζ.
quarter-car-settling-design = Este ajuste, ζ = { $zeta }, acomoda-se em { $time }.
quarter-car-settling-design-never = Este ajuste, ζ = { $zeta }, nunca se acomoda.
quarter-car-sensitivity-range = Com a massa suspensa entre { $low } e { $high } (±{ $variation }) e o mesmo amortecedor e a mesma mola, ζ vai de { $min } a { $max } (nominal { $nominal }); a estimativa linear é de { $linear_min } a { $linear_max }.
quarter-car-sensitivity-undefined = A faixa da razão de amortecimento não está definida para este ajuste.
quarter-car-sensitivity-inside = O ζ de acomodação mais rápida, { $zeta }, está dentro desta faixa: cargas que levam ζ abaixo dele se acomodam bem mais tarde.
quarter-car-sensitivity-outside = O ζ de acomodação mais rápida, { $zeta }, está fora desta faixa.
quarter-car-schematic = Quarto de veículo em t = { $time }: a carroceria está { $displacement } { $side ->
        [above] acima
       *[below] abaixo
    } do repouso, pista fixa.
quarter-car-settling-title = Tempo de acomodação em ±{ $band } de x₀ em função de ζ
quarter-car-axis-zeta = razão de amortecimento ζ
quarter-car-axis-zeta-fastest = razão de amortecimento ζ (tracejado: ζ mais rápido = { $zeta })
quarter-car-axis-settling-time = tempo de acomodação t_s
quarter-car-axis-sprung-mass = massa suspensa m
quarter-car-fastest = ζ mais rápido = { $zeta }
quarter-car-this-design = este ajuste
quarter-car-nominal = nominal
quarter-car-road = pista
quarter-car-band-label = ±{ $band } de x₀
quarter-car-series-design = este ajuste, ζ { $zeta }
quarter-car-title = Suspensão de quarto de veículo
quarter-car-summary = Um canto de um carro: a carroceria (massa suspensa m) sobre uma mola k e um amortecedor c acima de uma pista fixa, deslocada de x₀ e solta a partir do repouso (x′(0) = 0). c e ζ são duas visões do mesmo amortecedor, c = 2ζ√(km): mova um e o outro acompanha; mudar m ou k mantém o amortecedor, e assim ζ muda. As curvas finas mostram os ajustes clássicos neste carro: o de conforto (ζ ≈ 0,3–0,4) tem ressalto, o esportivo (ζ ≈ 0,65–0,7) se acomoda mais rápido, e os ajustes crítico (ζ = 1) e superamortecido voltam sem ressalto, porém mais devagar. O tempo de acomodação salta quando ζ passa pelos valores em que um ressalto cai dentro da faixa: o ζ mais rápido fica logo após um desses saltos, de modo que uma carga maior pode desajustar um carro bem ajustado (veja o gráfico da massa). A acomodação é medida nesta resposta livre: o tempo de acomodação é o último instante em que |x| é igual a faixa·|x₀|, após o qual a carroceria permanece dentro de ±faixa·|x₀| em torno do repouso (e não na faixa em torno do valor final de uma resposta ao degrau).
quarter-car-param-m = massa suspensa
quarter-car-param-k = rigidez da mola
quarter-car-param-c = coeficiente do amortecedor
quarter-car-param-zeta = razão de amortecimento
quarter-car-param-x0 = deslocamento inicial
quarter-car-param-band = faixa de acomodação em torno do repouso, relativa a x₀
quarter-car-param-dm = variação da massa suspensa
quarter-car-readout-regime = regime
quarter-car-readout-wn = frequência natural ωₙ
quarter-car-readout-fn = frequência natural fₙ
quarter-car-readout-zeta = razão de amortecimento ζ
quarter-car-readout-c = coeficiente do amortecedor c em uso
quarter-car-readout-c-crit = amortecimento crítico 2√(km)
quarter-car-readout-wd = frequência amortecida ω_d
quarter-car-readout-settling-time = tempo de acomodação t_s em ±faixa·|x₀| (resposta livre)
quarter-car-readout-overshoot = ressalto máximo (relativo a x₀)
quarter-car-readout-peak-time = instante do ressalto máximo
quarter-car-readout-zeta-argmin = ζ de acomodação mais rápida (resposta livre, mesma faixa)
quarter-car-readout-settling-min = seu tempo de acomodação
quarter-car-readout-zeta-lo = ζ com massa +dm %
quarter-car-readout-zeta-hi = ζ com massa −dm %
quarter-car-plot-response = Deslocamento da carroceria x(t)
quarter-car-plot-settling = Tempo de acomodação da resposta livre em função de ζ
quarter-car-plot-sensitivity = ζ quando a massa suspensa varia
quarter-car-preset-1 = Conforto ζ = 0,3
quarter-car-preset-2 = Conforto ζ = 0,4
quarter-car-preset-3 = Esportivo ζ = 0,65
quarter-car-preset-4 = Esportivo ζ = 0,7
quarter-car-preset-5 = Crítico ζ = 1
quarter-car-preset-6 = Superamortecido ζ = 2

### quarter-car-2dof

quarter-car-2dof-describe-motion = Sobre { $road ->
        [bump] uma lombada
        [step] um degrau
        [sine] uma pista senoidal
       *[random] uma pista aleatória
    } (altura máxima da pista { $road_peak }), a carroceria se desloca no máximo { $body } (em { $body_time }) e a roda no máximo { $wheel } (em { $wheel_time }).
quarter-car-2dof-describe-acceleration = A aceleração da carroceria atinge o pico de { $peak } ({ $peak_g } g); ao longo do percurso a partir do repouso, de 0 a { $window }, seu valor RMS é { $rms }.
quarter-car-2dof-describe-tyre-lift-off = A deflexão do pneu (roda acima da pista, positiva = pneu descarregando) vai de { $low } a { $high }, valor RMS { $rms }; ela atinge a deflexão estática { $limit } pela primeira vez em { $time }, quando a força do pneu cai a zero e a roda perde contato com a pista: perdas de contato { $lift_offs }; tempo fora da pista { $airborne }.
quarter-car-2dof-describe-tyre-contact = A deflexão do pneu (roda acima da pista, positiva = pneu descarregando) vai de { $low } a { $high }, valor RMS { $rms }; ela fica abaixo da deflexão estática { $limit }, de modo que o pneu mantém contato com a pista.
quarter-car-2dof-describe-frf = Resposta em frequência por unidade de altura da pista, em eixos logarítmicos. A carroceria acompanha as ondulações lentas da pista (razão 1), tem pico de { $body_peak } perto da oscilação vertical da carroceria, { $body_frequency }, e fica isolada acima disso: { $at_20 } a 20 Hz. A deflexão do pneu tem pico de { $tyre_peak } perto do salto da roda, { $tyre_frequency }.
quarter-car-2dof-schematic = Quarto de veículo em t = { $time }: carroceria { $body }, roda { $wheel }, pista { $road } (desenhadas em escala comum).
quarter-car-2dof-schematic-title = Esquema
quarter-car-2dof-axis-height = altura a partir do equilíbrio
quarter-car-2dof-axis-acceleration = aceleração z_s″
quarter-car-2dof-axis-tyre-deflection = deflexão do pneu z_u − u
quarter-car-2dof-axis-frequency = frequência f
quarter-car-2dof-axis-magnitude = magnitude por unidade de altura da pista
quarter-car-2dof-series-road = pista u
quarter-car-2dof-series-wheel = roda z_u
quarter-car-2dof-series-body = carroceria z_s
quarter-car-2dof-series-body-acceleration = aceleração da carroceria
quarter-car-2dof-series-rms = ± RMS
quarter-car-2dof-series-lift-off = perda de contato (deflexão estática)
quarter-car-2dof-series-off-road = roda fora da pista
quarter-car-2dof-series-body-gain = carroceria/pista
quarter-car-2dof-series-tyre-gain = defl. pneu/pista
quarter-car-2dof-marker-road = pista
quarter-car-2dof-title = Quarto de veículo com carroceria e roda
quarter-car-2dof-summary = Duas massas, dois modos. A carroceria (massa suspensa m_s) apoia-se na mola da suspensão k_s e no amortecedor c_s; a roda (massa não suspensa m_u) apoia-se na mola do pneu k_t, que segue a pista u(t). A oscilação vertical da carroceria, em torno de 1–1,5 Hz, é a carroceria se movendo sobre a suspensão macia; o salto da roda, em torno de 10–15 Hz, é a roda leve quicando entre o pneu rígido e a suspensão. As respostas em frequência mostram os dois: a carroceria acompanha as ondulações lentas da pista, passa por cima das rápidas e vibra mais perto da oscilação vertical; a deflexão do pneu, que decide a aderência, tem pico no salto da roda. O pneu só pode empurrar: quando a roda sobe além da sua deflexão estática, a força do pneu é zero e a roda perde contato com a pista até tocá-la de novo. O conforto é avaliado pela aceleração RMS da carroceria, e a aderência pela deflexão RMS do pneu, ambas ao longo do percurso a partir do repouso, 0 … T. A resposta é exata entre as amostras da pista, próximas o bastante para seguir cada lombada e cada salto da roda. Os deslocamentos são medidos a partir do equilíbrio estático, positivos para cima; a pista aleatória soma 64 senoides com o espectro ISO 8608 em 0,5–20 Hz. Nela, a página mostra também a aceleração RMS estacionária da carroceria na pista ISO 8608 completa, sem ponderação e ponderada pelo W_k da ISO 2631-1 (a_w, a medida de conforto), obtida da equação de Lyapunov do carro.
quarter-car-2dof-param-ms = massa da carroceria (suspensa)
quarter-car-2dof-param-mu = massa da roda (não suspensa)
quarter-car-2dof-param-ks = rigidez da suspensão
quarter-car-2dof-param-kt = rigidez do pneu
quarter-car-2dof-param-cs = amortecimento da suspensão
quarter-car-2dof-param-road = excitação da pista
quarter-car-2dof-param-road-bump = lombada única (1 − cos)
quarter-car-2dof-param-road-step = degrau (meio-fio)
quarter-car-2dof-param-road-sine = senoide
quarter-car-2dof-param-road-random = pista aleatória (ISO 8608)
quarter-car-2dof-param-h = altura da lombada ou do degrau, amplitude da senoide
quarter-car-2dof-param-L = comprimento da lombada
quarter-car-2dof-param-V = velocidade
quarter-car-2dof-param-f-road = frequência da pista senoidal
quarter-car-2dof-param-class = classe da pista aleatória
quarter-car-2dof-param-class-A = A (muito boa)
quarter-car-2dof-param-class-B = B (boa)
quarter-car-2dof-param-class-C = C (média)
quarter-car-2dof-param-class-D = D (ruim)
quarter-car-2dof-param-class-E = E (muito ruim)
quarter-car-2dof-param-class-F = F
quarter-car-2dof-param-class-G = G
quarter-car-2dof-param-class-H = H
quarter-car-2dof-param-seed = semente da pista aleatória
quarter-car-2dof-readout-f-body = frequência de oscilação vertical da carroceria
quarter-car-2dof-readout-f-wheel = frequência de salto da roda
quarter-car-2dof-readout-window = janela do RMS: o percurso a partir do repouso, 0 … T
quarter-car-2dof-readout-rms-body-accel = aceleração RMS da carroceria em 0 … T (conforto)
quarter-car-2dof-readout-rms-tyre-deflection = deflexão RMS do pneu z_u − u em 0 … T (aderência)
quarter-car-2dof-readout-max-travel = maior curso da suspensão |z_s − z_u|
quarter-car-2dof-readout-static-tyre-deflection = deflexão estática do pneu (além dela, a roda perde contato)
quarter-car-2dof-readout-lift-off = primeira perda de contato: a força do pneu chega a zero
quarter-car-2dof-readout-airborne-time = tempo com a roda fora da pista
quarter-car-2dof-readout-rms-road = altura RMS da pista (pista aleatória)
quarter-car-2dof-readout-stationary-accel = aceleração RMS estacionária da carroceria, pista ISO 8608 completa (pista aleatória)
quarter-car-2dof-readout-stationary-weighted-accel = a_w estacionária: aceleração RMS da carroceria ponderada pelo W_k da ISO 2631-1 (pista aleatória)
quarter-car-2dof-readout-body-gain = amplitude carroceria / pista na frequência da senoide
quarter-car-2dof-readout-tyre-gain = deflexão do pneu / amplitude da pista na frequência da senoide
quarter-car-2dof-plot-motion = Carroceria, roda e pista
quarter-car-2dof-plot-accel = Aceleração da carroceria
quarter-car-2dof-plot-frf = Resposta em frequência por unidade de altura da pista
quarter-car-2dof-plot-tyre = Deflexão do pneu
quarter-car-2dof-preset-1 = Lombada de 5 cm a 10 m/s
quarter-car-2dof-preset-2 = Meio-fio de 5 cm
quarter-car-2dof-preset-3 = Ondulação na oscilação vertical da carroceria
quarter-car-2dof-preset-4 = Ondulação no salto da roda
quarter-car-2dof-preset-5 = Pista aleatória, classe C, 20 m/s
quarter-car-2dof-preset-6 = Amortecedor macio em pista ruim


### paper

paper-unavailable = a demonstração desta figura não está disponível
paper-pending-plot = desenhado quando o aplicativo completo carregar
paper-pending-mark = carregando…
paper-pending-value = …
paper-pending = Verificado assim que o aplicativo completo carregar, em instantes.
paper-figure = Figura { $number }
paper-section = Seção { $number }
paper-section-figure = Seção { $section }, figura { $figure }
paper-near-agrees = A demonstração calcula { $computed }, que coincide, dentro do arredondamento, com o valor do artigo, { $claimed } (tolerância ±{ $tolerance }).
paper-near-differs = A demonstração calcula { $computed }, e não o valor do artigo, { $claimed } (tolerância ±{ $tolerance }).
paper-below-agrees = A demonstração calcula { $computed }, abaixo do limite de { $bound } dado pelo artigo.
paper-below-differs = A demonstração calcula { $computed }, acima do limite de { $bound } dado pelo artigo.
paper-range = { $low } a { $high }
paper-range-agrees = A demonstração calcula de { $low } a { $high }, como diz o artigo.
paper-range-differs = A demonstração calcula de { $low } a { $high }, e não o intervalo do artigo.
paper-peak = O máximo de |H(r)| encontrado por busca está em r = { $found }, onde a fórmula dá { $formula }.
paper-slope = Com o passo do artigo, h = { $step }, e cinco reduções à metade (até { $smallest }), a inclinação ajustada é { $slope }.
paper-reason-context = { $verdict } { $context }
paper-exhibit-fig1a = Resposta livre do quarto de carro (m = 300 kg, k = 24 kN/m, x₀ = 60 mm) com os ajustes de conforto, desempenho, crítico e superamortecido.
paper-exhibit-fig1b = Tempo de acomodação em função da razão de amortecimento, com seu mínimo.
paper-exhibit-fig2a = Corrente no circuito RLC série (L = 0,5 H, C = 20 mF, V₀ = 12 V) à medida que a resistência percorre os regimes.
paper-exhibit-fig2b = Tensão no capacitor do mesmo circuito.
paper-exhibit-fig3a = Módulo da resposta em frequência para uma família de razões de amortecimento.
paper-exhibit-fig3b = Fase da resposta em frequência.
paper-exhibit-fig4a = Euler e RK4 comparados à resposta exata de um oscilador levemente amortecido (ζ = 0,05, ωₙ = 2 rad/s) com h = 0,3 s.
paper-exhibit-fig4b = Erro máximo em função do passo em eixos log–log, com as inclinações.
paper-exhibit-fig5 = Uma equação em muitas máquinas: sistemas mecânicos, elétricos e outros regidos pela mesma equação a·y'' + b·y' + c·y = f(t).
paper-exhibit-table1 = A analogia mecânico–elétrica: massa ↔ indutância, amortecedor ↔ resistência, mola ↔ 1/capacitância.
paper-exhibit-table2 = Os regimes de amortecimento: condição, raízes, comportamento e exemplos.
paper-exhibit-table3 = Os métodos de integração comparados: erro, ordem e estabilidade com um mesmo passo.
paper-claim-fig1-zeta-optimum = Uma razão de amortecimento de cerca de 0,7 dá o menor tempo de acomodação (faixa de 5 %).
paper-claim-sec3-natural-frequency = A frequência natural do quarto de carro é de cerca de 8,9 rad/s (cerca de 1,4 Hz).
paper-claim-sec4-critical-resistance = O circuito é criticamente amortecido com R = 2√(L/C) = 10 Ω.
paper-claim-fig3-q-factor = Q = 10 com ζ = 0,05.
paper-claim-fig3-q-factor-light = Q = 50 com ζ = 0,01.
paper-claim-sec5-peak-frequency = A resposta atinge o pico em ω = ωₙ√(1 − 2ζ²), logo abaixo de ωₙ (verificado com ζ = 0,1).
paper-claim-fig4-euler-error = Com h = 0,3 s, o erro máximo de Euler é de cerca de 0,08.
paper-claim-fig4-rk4-error = Com h = 0,3 s, o erro máximo do RK4 é menor que 0,001.
paper-claim-fig4-euler-slope = O erro de Euler cai com inclinação ≈ 1 no gráfico log–log.
paper-claim-sec7-mass-tolerance = Uma incerteza de ±10 % na massa suspensa leva ζ = 1,0 a um valor entre 0,91 e 1,10.
paper-claim-fig1-zeta-optimum-context = Para uma faixa de 2 %, o ζ de acomodação mais rápida passa a ser { $value }.
paper-claim-sec3-natural-frequency-context = Em hertz: fₙ = { $value }.
paper-claim-fig4-euler-error-context = Euler é instável com este passo: |1 + hλ| = { $value } por passo, então seu erro cresce sem limite.
paper-claim-fig4-rk4-error-context = O RK4 é estável com este passo (|R(hλ)| = { $value } por passo), mas ao longo de toda a janela seu erro excede o limite.
paper-claim-fig4-euler-slope-context = A ordem ajustada com passos pequenos, onde o erro é assintótico, é { $value }.
paper-claim-sec7-mass-tolerance-context = ζ = c/(2√(km)) varia como 1/√m, então uma variação de ±10 % na massa o altera apenas cerca de ±5 % (ωₙ cai para { $value } com +10 %).
paper-title = O artigo, verificado
paper-summary = O Zeta Lab foi construído a partir de um artigo sobre equações diferenciais de segunda ordem em sistemas mecânicos e elétricos (Ihenacho, Samuel, Okechukwu et al., Science Publishing Group, 2026). Aqui estão todas as suas figuras e tabelas, desenhadas ao vivo pela demonstração que as reproduz, e todos os números que ele afirma, verificados: cada afirmação mostra o valor do artigo, o valor que o aplicativo calcula e um veredito. Siga um link para abrir a demonstração exatamente nesse estado.
paper-readout-claims = afirmações verificadas
paper-readout-confirmed = afirmações confirmadas
paper-readout-differs = afirmações que divergem
paper-plot-fig1a = Figura 1(a)
paper-plot-fig1b = Figura 1(b)
paper-plot-fig2a = Figura 2(a)
paper-plot-fig2b = Figura 2(b)
paper-plot-fig3a = Figura 3(a)
paper-plot-fig3b = Figura 3(b)
paper-plot-fig4a = Figura 4(a)
paper-plot-fig4b = Figura 4(b)
paper-plot-fig5 = Figura 5
paper-plot-table1 = Tabela 1
paper-plot-table2 = Tabela 2
paper-plot-table3 = Tabela 3

### resonance

resonance-axis-ratio = razão de frequências r = ω/ωₙ
resonance-axis-amplification = amplificação |H| = X/(F₀/k)
resonance-axis-magnitude-db = magnitude 20·log₁₀|H|
resonance-axis-phase = fase ∠H (atraso de x em relação a F)
resonance-plot-magnitude-db = Amplificação |H(r)| em dB
resonance-family = família ζ = { $from } … { $to }
resonance-current = ζ atual = { $zeta }
resonance-drive = excitação r = { $ratio }
resonance-peak = pico
resonance-quadrature = −90° em r = 1
resonance-legend-width = largura de meia potência r₂ − r₁ = { $width }
resonance-legend-broad = |H| ≥ |H|max/√2 até r = { $upper }
resonance-legend-cutoff = corte de −3 dB em r = { $upper }
resonance-band-width = pontos de meia potência (|H| = |H|max/√2) em r = { $lower } e { $upper }: largura do pico r₂ − r₁ = { $width }
resonance-band-broad = |H| fica acima de |H|max/√2 de r = 0 até r = { $upper }: o pico não tem ponto inferior de meia potência, portanto sua largura de meia potência é indefinida
resonance-band-cutoff = |H| cai para 1/√2 do seu valor estático (−3 dB) no corte r = { $upper }; sem pico não há largura de meia potência
resonance-peak-at = pico de ressonância { $gain } em r = { $ratio }
resonance-no-peak = sem pico de ressonância (ζ ≥ 1/√2): |H| apenas decresce a partir de 1 em r = 0
resonance-describe-magnitude = { $view ->
        [db] Magnitude em dB para ζ = { $zeta }: { $peak }; { $band }. Na excitação r = { $drive }, a amplificação é { $gain }.
       *[linear] Magnitude para ζ = { $zeta }: { $peak }; { $band }. Na excitação r = { $drive }, a amplificação é { $gain }.
    }
resonance-describe-phase = Atraso de fase do deslocamento em relação à força para ζ = { $zeta }: 0° em baixa frequência, −90° em r = 1 para qualquer razão de amortecimento, tendendo a −180° acima da ressonância; quanto menor ζ, mais brusca a transição. Na excitação r = { $drive }, o atraso é { $degrees } ({ $radians } rad).
resonance-envelope = envoltória ±E(t)
resonance-steady-amplitude = amplitude em regime permanente ±X
resonance-describe-time-growing = Excitada a partir do repouso em r = { $ratio } (ω = { $omega }) durante { $span }: não há regime permanente; a amplitude cresce e chega a { $largest }.
resonance-describe-time = { $case ->
        [beats] Excitada a partir do repouso em r = { $ratio } (ω = { $omega }) durante { $span }: os movimentos livre e forçado batem com período { $period } (constante de tempo do decaimento { $tau }), tendendo à amplitude em regime permanente { $amplitude }, com atraso de { $lag } em relação à força. Maior afastamento mostrado: { $largest }.
        [build-up] Excitada a partir do repouso em r = { $ratio } (ω = { $omega }) durante { $span }: na ressonância a amplitude cresce em direção à amplitude em regime permanente { $amplitude } com constante de tempo 1/(ζωₙ) = { $tau }, com atraso de { $lag } em relação à força. Maior afastamento mostrado: { $largest }.
       *[transient] Excitada a partir do repouso em r = { $ratio } (ω = { $omega }) durante { $span }: após um transitório (constante de tempo { $tau }) ela se acomoda na amplitude em regime permanente { $amplitude }, com atraso de { $lag } em relação à força. Maior afastamento mostrado: { $largest }.
    }
resonance-fixed-base = base fixa
resonance-schematic = Massa sobre mola e amortecedor acima de uma base fixa, empurrada pela força F(t) = { $force } (seta acima da massa) em t = { $time }: deslocada { $displacement } do repouso.
resonance-beats-visible = visíveis
resonance-beats-no-free-oscillation = nenhum (sem oscilação livre, ζ ≥ 1)
resonance-beats-no-drive = nenhum (força constante)
resonance-beats-same-frequency = nenhum (excitação em ω_d)
resonance-beats-too-fast = nenhum (tão rápido quanto a oscilação)
resonance-beats-dies-out = nenhum (o movimento livre se extingue antes)
resonance-title = Ressonância forçada
resonance-summary = Uma massa de 1 kg sobre uma mola (k = ωₙ²·m) e um amortecedor (c = 2ζωₙ·m), em repouso, é excitada a partir de t = 0 por F(t) = F₀·cos(ωt). Em regime permanente, ela se move na frequência de excitação com amplitude |H(r)|·F₀/k, atrasada em relação à força pela fase de H, onde r = ω/ωₙ. Um amortecimento leve produz um pico alto e estreito perto de r = 1 (altura ≈ Q = 1/(2ζ)). Sua largura de meia potência, r₂ − r₁ entre as duas razões de frequência em que |H| = |H|max/√2, é ≈ 2ζ para amortecimento leve; acima de ζ ≈ 0,383 o ponto inferior chega a r = 0 e a largura fica indefinida, e acima de ζ = 1/√2 não há pico algum. Excitada exatamente na ressonância, a amplitude cresce ao longo de algumas constantes de tempo 1/(ζωₙ) sem batimento; excitada perto dela, os movimentos livre e forçado batem entre si até que a parte livre se extinga.
resonance-param-zeta = razão de amortecimento
resonance-param-r = razão de excitação ω/ωₙ
resonance-param-wn = frequência natural
resonance-param-F0 = amplitude da força
resonance-param-view = escala da magnitude
resonance-param-view-linear = |H| linear
resonance-param-view-db = decibéis 20·log₁₀|H|
resonance-readout-peak-gain = pico de ressonância |H|max
resonance-readout-peak-ratio = pico em r = ω/ωₙ
resonance-readout-Q = fator de qualidade Q = 1/(2ζ)
resonance-readout-peak-width = largura de meia potência do pico de |H| r₂ − r₁ (ζ < 0,383)
resonance-readout-gain-at-r = ganho |H(r)| na excitação
resonance-readout-phase-at-r = fase ∠H(r) na excitação
resonance-readout-amplitude = amplitude em regime permanente X = |H|·F₀/k
resonance-readout-beat-period = período de batimento 2π/|ω − ω_d| (enquanto há batimento)
resonance-readout-beats = batimentos em x(t)
resonance-plot-magnitude = Amplificação |H(r)|
resonance-plot-phase = Fase ∠H(r)
resonance-plot-time = Resposta a partir do repouso x(t)
resonance-preset-1 = Na ressonância, ζ = 0,05
resonance-preset-2 = Batimento perto da ressonância, r = 0,9
resonance-preset-3 = Sem pico, ζ ≈ 1/√2
resonance-preset-4 = Quase estático, r = 0,2
resonance-preset-5 = Isolamento, r = 3

### flutter

flutter-no-oscillation = sem oscilação
flutter-series-h-section = seção em H de 1940 (aprox. didática)
flutter-series-box = caixão aerodinâmico (placa plana, Theodorsen)
flutter-series-simplest = A₂* equivalente ao modelo mais simples
flutter-series-simplest-line = modelo mais simples ζ_s − g·U
flutter-axis-reduced-velocity = velocidade reduzida U/(f·B) = 2π/K
flutter-axis-wind-speed = velocidade do vento U
flutter-axis-effective-damping = razão de amortecimento efetiva ζ_eff
flutter-axis-twist = torção θ
flutter-threshold = limiar 4Iζ_s/(ρB⁴) = { $value }
flutter-upper-pole = polo superior
flutter-lower-pole = polo inferior
flutter-amplitude = amplitude ±a(t)
flutter-limit-cycle = ciclo limite ±{ $amplitude }
flutter-describe-derivative = A₂* em função da velocidade reduzida para { $model ->
        [h] a seção em H de 1940 (aproximação didática, não valores medidos)
        [box] o caixão aerodinâmico, idealizado como uma placa plana delgada (valores exatos de Theodorsen em escoamento potencial)
       *[simplest] o modelo mais simples (o A₂* a que equivale sua reta em U)
    }: a torção cresce onde A₂* ultrapassa 4Iζ_s/(ρB⁴).
flutter-describe-derivative-now = { $description } Com U = { $speed } (K = { $k }, U/(fB) = { $reduced_velocity }), A₂* = { $a2 }, { $side ->
        [above] acima do
       *[below] abaixo do
    } limiar { $threshold }.
flutter-describe-damping = Razão de amortecimento efetiva { $model ->
        [h] da seção em H de 1940
        [box] do caixão aerodinâmico
       *[simplest] do modelo mais simples
    }, a partir de ζ_s = { $zeta_s } com ar parado; { $crossing ->
        [inside] ela se anula na velocidade crítica { $speed }
        [beyond] ela só se anularia em { $speed }, além do máximo traçado, { $limit }
       *[never] ela nunca se anula até 100 m/s: o vento só acrescenta amortecimento
    }.
flutter-describe-damping-now = { $description } Com U = { $speed }, ela vale { $zeta }, { $sign ->
        [positive] positiva (estável)
        [negative] negativa (flutter)
       *[zero] zero
    }.
flutter-describe-damping-still = { $description } Com este vento, o tabuleiro não oscila.
flutter-describe-locus = Par de polos à medida que o vento aumenta: { $re_calm } ± { $im_calm }i 1/s com ar parado, { $re_end } ± { $im_end }i 1/s a { $limit }, { $crosses ->
        [yes] cruzando o eixo imaginário em U_crit
       *[no] sem nunca cruzar o eixo imaginário
    }.
flutter-describe-locus-now = { $description } Com U = { $speed }, os polos são { $re } ± { $im }i 1/s, no semiplano { $side ->
        [right] direito (instável)
       *[left] esquerdo (estável)
    }.
flutter-oscillation = a oscilação
flutter-oscillation-at = a oscilação de { $frequency } Hz
flutter-describe-response = { $regime }: a partir de uma torção inicial de { $twist }, { $oscillation } { $case ->
        [settling] cresce até { $end } no fim do gráfico ({ $window }), estabilizando-se perto do ciclo limite de { $limit } (90 % dele após { $time })
        [slow] cresce apenas até { $end } no fim do gráfico ({ $window }); levaria { $time } para atingir 90 % do ciclo limite de { $limit }
        [settled] estabiliza-se no ciclo limite de { $limit } até o fim do gráfico ({ $window })
        [grows] cresce até { $end } no fim do gráfico ({ $window })
       *[dies] diminui até { $end } no fim do gráfico ({ $window })
    }.
flutter-describe-response-torn = { $description } Uma torção tão grande teria destruído qualquer tabuleiro muito antes; o limite é apenas uma hipótese didática.
flutter-schematic-title = Seção transversal do tabuleiro
flutter-drawn-clipped = desenhado cortado em { $angle }
flutter-drawn-true-scale = desenhado em escala real
flutter-drawn-larger = desenhado { $factor } vezes maior
flutter-drawn-note = ({ $drawn })
flutter-schematic = Seção transversal do tabuleiro da ponte em t = { $time }: torcida { $twist } ({ $drawn }), vento de { $wind } vindo da esquerda.
flutter-wind = vento U = { $speed }
flutter-title = Flutter: a ponte de Tacoma Narrows
flutter-summary = Um vento constante pode fornecer energia a um tabuleiro de ponte em torção por meio do seu próprio movimento. Scanlan escreveu o momento do vento sobre um tabuleiro em torção com derivadas de flutter medidas em túneis de vento: A₂* multiplica a velocidade de torção (um termo de amortecimento) e A₃* a torção (um termo de rigidez), ambas funções da frequência reduzida K = Bω/U. A razão de amortecimento do tabuleiro passa a ser ζ_eff ≈ ζ_s − ρB⁴A₂*(K)/(4I): para a seção em H, pouco aerodinâmica, do tabuleiro de Tacoma de 1940, A₂* muda de sinal à medida que o vento aumenta, e assim que ultrapassa o limiar 4Iζ_s/(ρB⁴) qualquer pequena torção cresce na frequência de torção própria do tabuleiro (perto de 0,2 Hz) — flutter (drapejamento), não ressonância: um vento constante não tem frequência a ser sintonizada, o próprio movimento gera sua excitação. A frequência é obtida por iteração em cada velocidade do vento, já que K depende dela. A teoria linear deixa a torção crescer indefinidamente; aqui se supõe que o termo de amortecimento do vento cai à metade com uma torção θ_s, o que limita o movimento a um grande ciclo limite, como em 7 de novembro de 1940, quando, com ventos de cerca de 42 mph, a torção cresceu em menos de uma hora até o tabuleiro se romper. Declarado como tal: A₂* e A₃* da seção em H são uma aproximação didática, curvas suaves com a forma dos resultados publicados de túnel de vento (Scanlan e Tomko 1971; Billah e Scanlan 1991), e não valores lidos deles; I, ζ_s e θ_s são supostos. O caixão aerodinâmico é idealizado como uma placa plana delgada, cujos A₂* e A₃* são exatos em escoamento potencial (Theodorsen 1935): seu A₂* permanece negativo, portanto nunca entra em flutter nessa faixa. O modelo mais simples ζ_eff = ζ_s − g·U é mantido para comparação.
flutter-param-U = velocidade do vento
flutter-param-model = modelo do momento do vento
flutter-param-model-scanlan = derivadas de flutter (Scanlan)
flutter-param-model-linear = modelo mais simples: ζ_eff = ζ_s − g·U
flutter-param-section = seção transversal do tabuleiro
flutter-param-section-h = seção em H de 1940 (vigas de alma cheia)
flutter-param-section-box = viga-caixão aerodinâmica
flutter-param-B = largura do tabuleiro
flutter-param-I = momento de inércia de massa por unidade de comprimento (suposto para 1940)
flutter-param-f0 = frequência de torção com ar parado
flutter-param-zeta-s = razão de amortecimento estrutural (suposta para 1940)
flutter-param-theta0 = torção inicial
flutter-param-theta-s = torção na qual o amortecimento do vento cai à metade (hipótese didática)
flutter-param-slope = modelo mais simples: amortecimento perdido por m/s
flutter-readout-regime = regime de uma pequena torção
flutter-readout-U-crit = velocidade crítica (de flutter) U_crit, buscada até 100 m/s
flutter-readout-zeta-eff = razão de amortecimento efetiva ζ_eff de uma pequena torção
flutter-readout-growth-rate = taxa de crescimento σ de uma pequena torção (< 0: decai)
flutter-readout-doubling-time = uma pequena torção dobra a cada
flutter-readout-frequency = frequência de torção no vento f
flutter-readout-K = frequência reduzida K = Bω/U
flutter-readout-reduced-velocity = velocidade reduzida U/(f·B) = 2π/K
flutter-readout-A2 = derivada de flutter A₂*(K)
flutter-readout-A3 = derivada de flutter A₃*(K)
flutter-readout-limit-deg = amplitude de torção do ciclo limite (com o limite suposto θ_s)
flutter-readout-time-to-large = tempo de θ₀ até 90 % do ciclo limite
flutter-readout-amplitude-end-deg = amplitude de torção no fim do gráfico
flutter-plot-derivative = Derivada de flutter A₂* e limiar de flutter
flutter-plot-damping = Amortecimento efetivo em função da velocidade do vento
flutter-plot-locus = Lugar das raízes à medida que o vento aumenta
flutter-plot-response = Torção do tabuleiro θ(t) ao longo de minutos
flutter-preset-1 = Tacoma 1940, 10 m/s (estável)
flutter-preset-2 = Tacoma 1940, 19 m/s (dia do colapso, ≈ 42 mph)
flutter-preset-3 = Tacoma 1940, vendaval de 30 m/s
flutter-preset-4 = Tabuleiro em caixão aerodinâmico, 19 m/s
flutter-preset-5 = Tabuleiro em caixão aerodinâmico, 40 m/s
flutter-preset-6 = Modelo mais simples, 19 m/s (ζ_eff = ζ_s − g·U)
flutter-table-caption = Flutter não é ressonância
flutter-table-column-1 = caso
flutter-table-column-2 = o que o alimenta
flutter-table-column-3 = frequência
flutter-table-column-4 = amortecimento
flutter-table-column-5 = amplitude
flutter-table-column-6 = solução
flutter-table-resonance-1 = Ressonância forçada (para comparação)
flutter-table-resonance-2 = uma força externa oscilando perto de ωₙ (passos em marcha, um motor)
flutter-table-resonance-3 = imposta pela força; deve coincidir com ωₙ
flutter-table-resonance-4 = positivo: limita o pico a cerca de 1/(2ζ) × o valor estático
flutter-table-resonance-5 = regime permanente limitado
flutter-table-resonance-6 = dessintonizar ou acrescentar amortecimento
flutter-table-underdamped-1 = Vento abaixo de U_crit
flutter-table-underdamped-2 = vento constante; momento ∝ velocidade de torção (A₂*) e torção (A₃*)
flutter-table-underdamped-3 = a própria do tabuleiro, um pouco deslocada por A₃*
flutter-table-underdamped-4 = ζ_eff > 0: A₂* abaixo do limiar 4Iζ_s/(ρB⁴)
flutter-table-underdamped-5 = uma torção se extingue
flutter-table-underdamped-6 = —
flutter-table-undamped-1 = Em U_crit
flutter-table-undamped-2 = vento constante; momento ∝ velocidade de torção (A₂*) e torção (A₃*)
flutter-table-undamped-3 = a própria do tabuleiro
flutter-table-undamped-4 = ζ_eff = 0: polos sobre o eixo imaginário
flutter-table-undamped-5 = uma torção persiste inalterada
flutter-table-undamped-6 = —
flutter-table-negatively-damped-1 = Flutter, vento acima de U_crit
flutter-table-negatively-damped-2 = vento constante; o próprio movimento gera sua excitação
flutter-table-negatively-damped-3 = a própria do tabuleiro, sem necessidade de sintonia
flutter-table-negatively-damped-4 = ζ_eff < 0: entra energia a cada ciclo
flutter-table-negatively-damped-5 = cresce até que o limite de amplitude (ou o tabuleiro) ceda
flutter-table-negatively-damped-6 = uma seção cujo A₂* permanece negativo: tabuleiro aerodinâmico, vazado ou enrijecido
### integrators

integrators-join = { "; " }
integrators-legend-dp45-order = DP45: { $order }
integrators-overflow-note = estouro em t = { $time }
integrators-failed = falhou
integrators-stable-yes = sim
integrators-stable-no = não
integrators-method-euler = Euler explícito
integrators-method-symplectic-euler = Euler simplético
integrators-method-heun = Heun
integrators-method-rk4 = RK4
integrators-legend-symplectic-euler = Euler simpl. ×
integrators-legend-euler = Euler
integrators-legend-heun = Heun
integrators-legend-dp45 = DP45 ● passos
integrators-legend-growing = { $legend } ×{ $growth }/passo ↑
integrators-legend-order = { $legend }: { $order }
integrators-legend-no-fit = { $legend }: sem ajuste
integrators-legend-dp45-no-order = DP45: sem ordem
integrators-series-exact = exata
integrators-axis-error = erro |x_num − x_exact|
integrators-axis-step = passo h
integrators-axis-max-error = erro máximo
integrators-axis-re = parte real Re(hλ)
integrators-axis-im = parte imaginária Im(hλ)
integrators-axis-evaluations = avaliações do lado direito N
integrators-limit-up-to = estável para h ≤ { $step }
integrators-limit-every = estável para todo h
integrators-limit-none = instável para todo h
integrators-method-overflows = { $method } estoura em t = { $time } (×{ $growth } por passo)
integrators-method-diverges = { $method } diverge (×{ $growth } por passo), erro máximo { $error }
integrators-method-diverges-clipped = { $method } diverge (×{ $growth } por passo, cortado), erro máximo { $error }
integrators-method-bounded = { $method } permanece limitado (×{ $growth } por passo), erro máximo { $error }
integrators-dp45-words = DP45 deu { $steps ->
        [one] { $steps } passo
       *[other] { $steps } passos
    } (tolerância { $tolerance }), erro máximo { $error }
integrators-dp45-failed = DP45 falhou: { $reason }
integrators-failed-underflow = o passo ficou pequeno demais para avançar em t = { $time } (o problema pode ser rígido demais ou singular)
integrators-failed-max-steps = desistiu em t = { $time } após { $steps } passos
integrators-failed-non-finite = a solução tornou-se infinita ou indefinida em t = { $time } (tente um passo menor)
integrators-describe-response = Cada método comparado com a oscilação amortecida exata ao longo de { $duration } com h = { $step } ({ $steps } passos). { $methods }. O gráfico mostra ±{ $range } vezes a amplitude exata; as curvas que passam disso são cortadas na borda.
integrators-describe-response-last = Cada método comparado com a oscilação amortecida exata ao longo de { $duration } com h = { $step } ({ $steps } passos, o último de { $last } para terminar em T). { $methods }. O gráfico mostra ±{ $range } vezes a amplitude exata; as curvas que passam disso são cortadas na borda.
integrators-error-peak = { $method }: máximo { $error } em t = { $time }
integrators-error-peak-growing = { $method }: máximo { $error } em t = { $time }, crescente
integrators-error-none = { $method }: nenhum erro finito
integrators-error-no-method = Nenhum método está ativado.
integrators-describe-error = Erro |x_num − x_exact| em escala logarítmica nos pontos da malha de cada método (h = { $step }): { $methods }.
integrators-describe-error-clipped = Erro |x_num − x_exact| em escala logarítmica nos pontos da malha de cada método (h = { $step }): { $methods }. Erros acima de { $clip } são cortados no topo.
integrators-fit = { $method }: inclinação ajustada { $slope } (h = { $from } … { $to })
integrators-fit-overflows = { $method }: inclinação ajustada { $slope } (h = { $from } … { $to }), estoura para h ≥ { $limit }
integrators-no-fit = { $method }: sem ajuste (poucos pontos na faixa assintótica)
integrators-no-fit-overflows = { $method }: sem ajuste (poucos pontos na faixa assintótica), estoura para h ≥ { $limit }
integrators-slope = inclinação { $order }
integrators-describe-convergence = Erro máximo em { $points } pontos de verificação comuns em função do passo h, para até { $levels } passos que se reduzem à metade a partir de { $from } (no máximo { $budget } passos por método no total, { $euler_budget } para Euler explícito; passos mais finos são omitidos). { $methods }. Cada ordem é ajustada apenas na faixa assintótica, desenhada como o segmento grosso: os passos mais finos cujas inclinações locais concordam dentro de { $spread }, com erros abaixo de { $ceiling } e acima de 1e-10 de x₀. As inclinações de referência 1 e 4 são pontilhadas; o h atual é a linha vertical tracejada. DP45 não tem um único h: veja o gráfico de trabalho–precisão.
integrators-off-scale = { $name } = { $value } (fora da escala)
integrators-path = hλ à medida que h cresce
integrators-z-real-pair = z = hλ = { $z1 } e { $z2 }
integrators-region-inside = { $method }: dentro da sua região, |R| = { $growth }, { $limit }
integrators-region-outside = { $method }: fora da sua região, |R| = { $growth }, { $limit }
integrators-describe-stability = Regiões de estabilidade |R(z)| ≤ 1 no plano complexo de z = hλ (o interior de cada curva fechada; a de Euler explícito é o disco |1 + z| ≤ 1). Os dois polos do sistema com h = { $step } dão { $z }. { $methods }. Euler simplético não é uma aplicação escalar R(z): sua matriz de passo 2×2 tem aqui raio espectral { $radius }, { $limit }. DP45 escolhe os próprios passos e os mantém estáveis.
integrators-work-words = { $method }: de { $error_first } com { $work_first } avaliações a { $error_last } com { $work_last }
integrators-describe-work = Erro máximo em função do trabalho que custou, contado em avaliações do lado direito f, em eixos log–log, para cada método: os de passo fixo nos passos do estudo de convergência (erro nos seus pontos de verificação comuns), DP45 nas tolerâncias { $from } … { $to } (erro nos seus passos aceitos). Mais abaixo é mais preciso, mais à esquerda é mais barato; um método de ordem p cai com inclinação −p; as execuções do DP45 são pontos onde a tolerância define os passos e cruzes onde a estabilidade os define. { $methods }.
integrators-provisional = Provisório: a partir de um estudo grosso (no máximo { $budget } passos por método, { $euler_budget } para Euler explícito; DP45 até { $tol }) enquanto o estudo completo ({ $full_budget } e { $full_euler_budget } passos; DP45 até { $full_tol }) é calculado. { $description }
integrators-runs-provisional = Provisório: as integrações até agora, até t = { $until } de { $duration }, enquanto o restante é calculado. { $description }
integrators-dp45-stability-runs = execuções cujos passos a estabilidade define (mais de { $share } dos passos a { $fraction } ou mais do seu maior passo estável): { $count }/{ $runs }
integrators-dp45-order = DP45: ordem observada { $order } (ajustada em { $from } … { $to } avaliações, onde a tolerância define os passos); { $runs }
integrators-dp45-no-order = DP45 não tem ordem observada: a estabilidade define seus passos, ou restam poucas execuções na faixa assintótica; { $runs }
integrators-title = Integradores numéricos e seu erro
integrators-summary = O oscilador livre integrado por Euler explícito, Euler simplético, Heun (RK2) e RK4 clássico com passo fixo h, e por Dormand–Prince 5(4) com passo adaptativo, cada um comparado com a solução exata. Um método de passo único multiplica cada modo por R(hλ) a cada passo: quando |R| > 1, os números crescem por melhor que o método aproxime a equação, e é por isso que Euler explícito faz explodir um oscilador pouco amortecido a menos que h < 2ζ/ωₙ. Quando ele é estável, reduzir h à metade divide o erro por 2^p, onde p é a ordem de convergência do método: o gráfico de convergência mede p. Desativar um método oculta suas curvas; suas leituras continuam sendo calculadas.
integrators-param-zeta = razão de amortecimento
integrators-param-wn = frequência natural
integrators-param-h = passo
integrators-param-T = duração
integrators-param-x0 = deslocamento inicial
integrators-param-tol = tolerância do DP45 (relativa; absoluta tol·x₀)
integrators-param-euler = Euler explícito
integrators-param-symplectic-euler = Euler simplético
integrators-param-heun = Heun (RK2)
integrators-param-rk4 = RK4
integrators-param-dp45 = Dormand–Prince 5(4), adaptativo
integrators-readout-h-used = passo usado, exceto o último
integrators-readout-h-last = último passo, que termina a execução em T
integrators-readout-max-err-euler = erro máximo, Euler explícito
integrators-readout-max-err-symplectic-euler = erro máximo, Euler simplético
integrators-readout-max-err-heun = erro máximo, Heun
integrators-readout-max-err-rk4 = erro máximo, RK4
integrators-readout-max-err-dp45 = erro máximo, DP45
integrators-readout-order-euler = ordem ajustada, Euler explícito
integrators-readout-order-symplectic-euler = ordem ajustada, Euler simplético
integrators-readout-order-heun = ordem ajustada, Heun
integrators-readout-order-rk4 = ordem ajustada, RK4
integrators-readout-order-dp45 = ordem observada, DP45 (erro em função das avaliações de f, onde a tolerância define os passos)
integrators-readout-stable-euler = estável com este h, Euler explícito
integrators-readout-stable-symplectic-euler = estável com este h, Euler simplético
integrators-readout-stable-heun = estável com este h, Heun
integrators-readout-stable-rk4 = estável com este h, RK4
integrators-readout-growth-euler = crescimento por passo |R(hλ)|, Euler explícito
integrators-readout-growth-symplectic-euler = crescimento por passo (raio espectral), Euler simplético
integrators-readout-growth-heun = crescimento por passo |R(hλ)|, Heun
integrators-readout-growth-rk4 = crescimento por passo |R(hλ)|, RK4
integrators-readout-steps-dp45 = passos aceitos pelo DP45
integrators-plot-response = Soluções numéricas e a x(t) exata
integrators-plot-error = Erro ao longo do tempo
integrators-plot-convergence = Convergência: erro máximo em função do passo h
integrators-plot-work = Trabalho–precisão: erro máximo em função das avaliações de f
integrators-plot-stability = Regiões de estabilidade e z = hλ
integrators-preset-1 = Pouco amortecido, h = 0,3 s
integrators-preset-2 = Euler no limite da estabilidade, h = 0,04 s
integrators-preset-3 = RK4 além do seu limite, h = 1,6 s
integrators-preset-4 = Não amortecido, h = 0,1 s
integrators-preset-5 = Rígido e superamortecido ζ = 2, ωₙ = 20
integrators-table-caption = Os métodos
integrators-table-column-1 = método
integrators-table-column-2 = ordem p
integrators-table-column-3 = avaliações de f por passo
integrators-table-column-4 = fator de amplificação R(z)
integrators-table-column-5 = num oscilador não amortecido
integrators-table-euler-1 = Euler explícito
integrators-table-euler-2 = 1
integrators-table-euler-3 = 1
integrators-table-euler-4 = 1 + z
integrators-table-euler-5 = sempre cresce: |R(iωh)| = √(1 + ω²h²) > 1
integrators-table-symplectic-euler-1 = Euler simplético
integrators-table-symplectic-euler-2 = 1
integrators-table-symplectic-euler-3 = 2
integrators-table-symplectic-euler-4 = matriz 2×2, não um R escalar
integrators-table-symplectic-euler-5 = erro de energia limitado enquanto ωh ≤ 2
integrators-table-heun-1 = Heun (RK2)
integrators-table-heun-2 = 2
integrators-table-heun-3 = 2
integrators-table-heun-4 = 1 + z + z²/2
integrators-table-heun-5 = cresce lentamente: |R(iy)|² = 1 + y⁴/4
integrators-table-rk4-1 = RK4 clássico
integrators-table-rk4-2 = 4
integrators-table-rk4-3 = 4
integrators-table-rk4-4 = 1 + z + z²/2 + z³/6 + z⁴/24
integrators-table-rk4-5 = amortece levemente enquanto ωh ≤ 2√2
integrators-table-dp45-1 = Dormand–Prince 5(4)
integrators-table-dp45-2 = 5
integrators-table-dp45-3 = 6 (a primeira igual à última)
integrators-table-dp45-4 = adaptativo: h segue a estimativa de erro
integrators-table-dp45-5 = estável: passos rejeitados reduzem h

### nonlinear

nonlinear-effect-linear = linear
nonlinear-effect-hardening = mola enrijecedora
nonlinear-effect-softening = mola amolecedora
nonlinear-effect-stick-slip = adere-desliza
nonlinear-effect-bump-stop = impacto no batente
nonlinear-effect-asymmetric = amortecedor assimétrico
nonlinear-effect-several = várias ao mesmo tempo
nonlinear-effect-escaped = fuga
nonlinear-join = { "; " }
nonlinear-differ = diferem em até { $deviation } em t = { $time }
nonlinear-first-swing = primeira oscilação { $nonlinear } contra { $linear } da linear (razão { $ratio })
nonlinear-sticks-at = o atrito prende a massa em { $position } a partir de { $time }
nonlinear-escapes = a simulação não linear sai do gráfico (|x| > { $limit }) em { $time }
nonlinear-describe-response = { $effect }: ambas começam juntas; { $clauses }.
nonlinear-describe-phase = Plano de fase: ambas as trajetórias começam em x = { $x0 }, v = { $v0 }. A linear descreve uma espiral em direção a ({ $x_linear }, { $v_linear }); a não linear termina em x = { $x_end }, v = { $v_end }, com velocidade máxima de { $speed } contra { $speed_linear } da linear.
nonlinear-describe-spring = Força restauradora em função da extensão em ±{ $reach }: a mola linear é a reta k·x; no maior curso, { $travel }, a força não linear é { $force } contra { $linear } da linear{ $stops ->
        [yes] , com os batentes somando { $rate } além de ±{ $gap }.
       *[no] .
    }
nonlinear-describe-damper = Força do amortecedor mais atrito em função da velocidade em ±{ $speed }: a +{ $speed } (distensão) vale { $rebound }, a −{ $speed } (compressão) { $compression }; o amortecedor médio do modelo linear dá ±{ $linear }{ $coulomb ->
        [yes] ; o atrito de deslizamento acrescenta um salto de ±{ $friction } em v = 0, e em repouso o atrito estático segura até ±{ $holding }.
       *[no] .
    }
nonlinear-axis-velocity-rebound = velocidade v (+ distensão)
nonlinear-series-stops = batentes ±{ $gap }
nonlinear-series-linear = modelo linear
nonlinear-series-nonlinear = não linear (RK4)
nonlinear-marker-sticks = adere
nonlinear-marker-start = início
nonlinear-series-linear-spring = k·x linear
nonlinear-series-spring = k·x + k₃·x³ + batentes
nonlinear-series-linear-damper = c̄·v linear
nonlinear-series-damper = amortecedor + atrito
nonlinear-schematic = Quarto de veículo em t = { $time }: suspensão estendida { $extension }{ $stops ->
        [pressing] , apoiada num batente.
        [clear] , sem tocar os batentes.
       *[none] .
    }
nonlinear-title = Além do modelo linear
nonlinear-summary = Uma suspensão real só é linear para movimentos pequenos. Aqui o quarto de veículo ganha uma mola cúbica (k₃ > 0 enrijecedora, k₃ < 0 amolecedora), um amortecedor mais duro na distensão (x′ > 0) do que na compressão, atrito de Coulomb nas articulações e batentes de borracha além de ±gap. O atrito alterna aderência e deslizamento: enquanto a massa desliza, ele freia com a força F_c; quando ela para, o atrito estático a segura até F_static, um múltiplo fixo de F_c, e ela só volta a se mover se a mola puxar com mais força. O movimento é integrado com RK4, cada parada localizada dentro do seu passo, e desenhado contra o modelo linear m·x″ + c̄·x′ + k·x = 0 (c̄ a constante média do amortecedor) a partir do mesmo início. Observe onde a previsão falha: o período depende da amplitude (a mola enrijecedora o encurta, a amolecedora o alonga), o atrito faz a amplitude cair em linha reta e depois prende a massa fora do centro de vez (adere-desliza), um batente transforma uma oscilação suave num impacto, e um amortecedor assimétrico desloca a posição média. Os valores padrão são um canto de carro plausível: 300 kg, 24 kN/m (1,4 Hz), um amortecedor de 1 500 N·s/m (ζ ≈ 0,28) e uma mola levemente progressiva. x é a extensão da suspensão a partir do equilíbrio estático (positiva = carroceria para cima).
nonlinear-param-m = massa suspensa
nonlinear-param-k = rigidez linear da mola
nonlinear-param-k3 = coeficiente cúbico da mola (+ enrijecedora, − amolecedora)
nonlinear-param-c-comp = constante do amortecedor na compressão
nonlinear-param-c-reb = constante do amortecedor na distensão
nonlinear-param-friction = força de atrito de Coulomb ao deslizar
nonlinear-param-stick-ratio = razão entre atrito estático e de deslizamento
nonlinear-param-gap = folga até o batente
nonlinear-param-k-stop = rigidez do batente (0 = sem batentes)
nonlinear-param-x0 = extensão inicial
nonlinear-param-v0 = velocidade inicial
nonlinear-readout-effect = não linearidade dominante
nonlinear-readout-period-ratio = razão dos períodos da primeira oscilação T_nonlinear / T_linear
nonlinear-readout-max-deviation = maior |x_nonlinear − x_linear|
nonlinear-readout-period-nonlinear = período não linear da primeira oscilação completa (três cruzamentos por zero)
nonlinear-readout-period-linear = período linear da primeira oscilação completa (= 2π/ω_d)
nonlinear-readout-max-travel = maior |x| (não linear)
nonlinear-readout-stick-position = o atrito prende a massa em
nonlinear-plot-response = Resposta não linear e linear x(t)
nonlinear-plot-phase = Plano de fase (x, v)
nonlinear-plot-spring = Força da mola e dos batentes
nonlinear-plot-damper = Força do amortecedor e do atrito
nonlinear-preset-1 = Linear (tudo desligado)
nonlinear-preset-2 = Mola enrijecedora
nonlinear-preset-3 = Mola amolecedora
nonlinear-preset-4 = Atrito adere–desliza
nonlinear-preset-5 = Impacto no batente
nonlinear-preset-6 = Amortecedor assimétrico
nonlinear-table-caption = Onde o modelo linear falha
nonlinear-table-column-1 = não linearidade
nonlinear-table-column-2 = lei de força
nonlinear-table-column-3 = o que o modelo linear não capta
nonlinear-table-column-4 = assinatura nos gráficos
nonlinear-table-linear-1 = Nenhuma (linear)
nonlinear-table-linear-2 = k·x + c·x′
nonlinear-table-linear-3 = nada: o modelo é exato
nonlinear-table-linear-4 = as duas curvas coincidem
nonlinear-table-hardening-spring-1 = Mola enrijecedora
nonlinear-table-hardening-spring-2 = k·x + k₃·x³, k₃ > 0
nonlinear-table-hardening-spring-3 = a frequência sobe com a amplitude
nonlinear-table-hardening-spring-4 = período mais curto enquanto a oscilação é grande; as curvas se afastam
nonlinear-table-softening-spring-1 = Mola amolecedora
nonlinear-table-softening-spring-2 = k·x + k₃·x³, k₃ < 0
nonlinear-table-softening-spring-3 = a frequência cai com a amplitude; além de √(−k/k₃) a mola cede
nonlinear-table-softening-spring-4 = período mais longo; um início grande pode escapar
nonlinear-table-stick-slip-1 = Atrito de Coulomb
nonlinear-table-stick-slip-2 = F_c·sgn(x′) ao deslizar; até F_static em repouso
nonlinear-table-stick-slip-3 = a amplitude cai cerca de 4F_c/k por ciclo, em linha reta, e depois a massa fica presa de vez onde |k·x| ≤ F_static
nonlinear-table-stick-slip-4 = envoltória reta; um final plano fora do zero
nonlinear-table-bump-stop-impact-1 = Batentes
nonlinear-table-bump-stop-impact-2 = k_stop·(|x| − gap) além de ±gap
nonlinear-table-bump-stop-impact-3 = um contato rígido e súbito: força grande, inversão rápida
nonlinear-table-bump-stop-impact-4 = picos cortados em ±gap; quebras no laço de fase
nonlinear-table-asymmetric-damper-1 = Amortecedor assimétrico
nonlinear-table-asymmetric-damper-2 = c_r·x′ na distensão, c_c·x′ na compressão
nonlinear-table-asymmetric-damper-3 = um deslocamento da posição média (efeito “jacking”) e semiciclos desiguais
nonlinear-table-asymmetric-damper-4 = decaimento desigual; a espiral de fase fica fora do centro
nonlinear-table-several-at-once-1 = Várias ao mesmo tempo
nonlinear-table-several-at-once-2 = soma das anteriores
nonlinear-table-several-at-once-3 = seus efeitos se somam e interagem
nonlinear-table-several-at-once-4 = ver cada linha
nonlinear-table-escaped-1 = Mola amolecedora além do seu limite
nonlinear-table-escaped-2 = k·x + k₃·x³ < 0 para |x| > √(−k/k₃)
nonlinear-table-escaped-3 = o modelo deixa de descrever uma suspensão
nonlinear-table-escaped-4 = a simulação é cortada onde |x| passa de 1 m

### uncertainty

uncertainty-quantity-zeta = razão de amortecimento ζ
uncertainty-quantity-f0 = frequência natural f0
uncertainty-quantity-q = fator de qualidade Q
uncertainty-quantity-bandwidth = largura de banda de meia potência
uncertainty-quantity-settling-time = tempo de acomodação da resposta livre (±5 %)
uncertainty-hist-title = Monte Carlo: { $quantity }
uncertainty-draws-provisional = { $draws } ({ $full } a caminho)
uncertainty-band-nominal-mass = m nominal
uncertainty-band-lowest-corner = canto de ζ mínimo
uncertainty-band-nominal = nominal
uncertainty-band-highest-corner = canto de ζ máximo
uncertainty-never = nunca
uncertainty-band-suspension = Resposta livre a partir de { $start } com a massa suspensa a +{ $percent } %, nominal e a −{ $percent } %
uncertainty-band-rlc = Tensão do capacitor a partir de 1 V no canto de ζ mínimo, no nominal e no canto de ζ máximo da caixa de tolerâncias
uncertainty-ignored-rlc = Os controles do RLC são ignorados.
uncertainty-ignored-suspension = Os controles da suspensão são ignorados.
uncertainty-zeta-undefined = ζ não está definido num extremo do intervalo
uncertainty-zeta-spans = ζ vai de { $low } a { $high }
uncertainty-describe-band = { $what }: { $zeta }; tempos de acomodação de 5 % (cruzes): { $first }, { $second } e { $third }. { $ignored }
uncertainty-dist-normal = normais (tolerância = 3σ)
uncertainty-dist-uniform = uniformes
uncertainty-spec-zeta = A janela de especificação de ζ, { $low }–{ $high }, está marcada; { $share } dos sorteios atendem a toda a especificação.
uncertainty-spec-settling-time = O limite de especificação, { $limit }, está marcado.
uncertainty-no-finite = Nenhum sorteio dá um valor finito de { $quantity }.
uncertainty-describe-histogram = Histograma de { $quantity } em { $draws } sorteios { $distribution }: de { $low } a { $high }, percentil 5: { $p5 }, percentil 95: { $p95 }.{ $marked ->
        [yes] {" "}{ $spec }
       *[no] {""}
    }
uncertainty-provisional-title = { $title } (provisório)
uncertainty-provisional-description = Provisório: a partir dos primeiros { $shown } sorteios enquanto a simulação de { $full } continua. { $description }
uncertainty-axis-capacitor-voltage = tensão do capacitor v_C
uncertainty-settling-band = faixa de acomodação de 5 %
uncertainty-axis-draws = sorteios
uncertainty-series-bins = sorteios por classe ({ $bins } classes)
uncertainty-no-finite-values = nenhum valor finito
uncertainty-spec-limit = limite de especificação
uncertainty-percentiles = percentis 5 e 95
uncertainty-title = Análise de tolerâncias
uncertainty-summary = Componentes reais não têm exatamente seu valor nominal. Escolha o sistema: o quarto de veículo (massa suspensa m, mola k e o amortecedor ajustado para ζ na massa nominal; a massa varia ±dm conforme a carga do veículo) ou o circuito RLC série (R, L e C, cada um dentro de ±dR, ±dL, ±dC). Só os controles do sistema escolhido são usados; o outro grupo é ignorado. Os intervalos exatos de ζ, ωₙ e Q vêm dos cantos da caixa de tolerâncias. A simulação de Monte Carlo sorteia N projetos (com semente: a mesma semente dá o mesmo resultado), uniformes dentro da tolerância ou normais com a tolerância como 3σ. O rendimento é a fração dos sorteios com ζ dentro da janela de especificação e um tempo de acomodação de 5 % (soltando do repouso) não maior que o limite.
uncertainty-param-system = sistema
uncertainty-param-system-suspension = suspensão de quarto de veículo
uncertainty-param-system-rlc = RLC série
uncertainty-param-m = suspensão: massa suspensa
uncertainty-param-k = suspensão: rigidez da mola
uncertainty-param-zeta = suspensão: ζ de projeto na massa nominal
uncertainty-param-dm = suspensão: tolerância da massa ±
uncertainty-param-R = RLC: resistência
uncertainty-param-L = RLC: indutância
uncertainty-param-C = RLC: capacitância
uncertainty-param-dR = RLC: tolerância do resistor ±
uncertainty-param-dL = RLC: tolerância do indutor ±
uncertainty-param-dC = RLC: tolerância do capacitor ±
uncertainty-param-dist = distribuição dos componentes
uncertainty-param-dist-uniform = uniforme dentro de ±tolerância
uncertainty-param-dist-normal = normal, tolerância = 3σ
uncertainty-param-N = sorteios de Monte Carlo
uncertainty-param-seed = semente aleatória
uncertainty-param-zeta-lo = especificação: ζ mínimo
uncertainty-param-zeta-hi = especificação: ζ máximo
uncertainty-param-ts-max = especificação: tempo de acomodação máximo
uncertainty-param-hist = segundo histograma
uncertainty-param-hist-zeta = razão de amortecimento ζ
uncertainty-param-hist-f0 = frequência natural f0
uncertainty-param-hist-q = fator de qualidade Q
uncertainty-param-hist-bandwidth = largura de banda
uncertainty-param-hist-settling-time = tempo de acomodação
uncertainty-readout-zeta-min = ζ, mínimo (exato)
uncertainty-readout-zeta-max = ζ, máximo (exato)
uncertainty-readout-wn-min = ωₙ, mínima (exata)
uncertainty-readout-wn-max = ωₙ, máxima (exata)
uncertainty-readout-Q-min = Q, mínimo (exato)
uncertainty-readout-Q-max = Q, máximo (exato)
uncertainty-readout-yield = rendimento (atende à especificação)
uncertainty-readout-zeta-p5 = ζ, percentil 5
uncertainty-readout-zeta-p95 = ζ, percentil 95
uncertainty-readout-Q-p5 = Q, percentil 5
uncertainty-readout-Q-p95 = Q, percentil 95
uncertainty-readout-draws = sorteios
uncertainty-readout-compute-time = tempo de cálculo do Monte Carlo
uncertainty-plot-band = Faixa de respostas livres dentro da tolerância
uncertainty-plot-zeta-hist = Monte Carlo: razão de amortecimento ζ
uncertainty-plot-hist = Monte Carlo: grandeza escolhida
uncertainty-preset-1 = Projeto com ζ = 1 e massa ±10 %
uncertainty-preset-2 = Projeto com ζ = 0,7 e massa ±10 %
uncertainty-preset-3 = RLC com componentes de 5 %
uncertainty-preset-4 = RLC com componentes de 20 %
# Zeta Lab — português (Brasil). Ids and variables as in en.ftl.

## A página

page-skip = Ir para a demonstração
page-demo = Demonstração
page-share = Compartilhar / Incorporar
page-loading = Carregando o solucionador…
page-footer = Zeta Lab — cada número desta página é calculado em Rust (compilado para WebAssembly) a partir de soluções exatas.
page-parameters = Parâmetros
page-readouts = Resultados
page-about = Sobre esta demonstração
page-plot-in-view = Gráfico em exibição
page-presets = Predefinições
page-reset = Restaurar padrões
page-exact-value = valor exato
page-export-group = Exportar { $plot }
page-download = Baixar { $plot } como { $format }
page-play = Reproduzir
page-pause = Pausar
page-sound-on = Som ligado
page-sound-off = Som desligado
page-sound-hint = Ouvir x(t): a altura do som acompanha o deslocamento
page-anim-time = Tempo da animação
page-time-words = tempo { $t } segundos
page-schematic = Esquema animado
page-dismiss = Fechar aviso
page-failed = Algo deu errado e a demonstração foi reiniciada: { $text }
page-no-demo = Não existe demonstração chamada “{ $id }”; exibindo { $fallback }.
page-no-wasm = Não foi possível carregar o solucionador ({ $text }). Esta página precisa de WebAssembly.
page-module-failed = Não foi possível carregar esta parte da página ({ $text }). Verifique a conexão e tente de novo.
page-copy = Copiar
page-equation = Equação
page-tour-head = O artigo, figura por figura
page-tour-open = Abrir este estado na demonstração
page-tour-paper = O artigo diz
page-tour-app = O aplicativo calcula
page-tour-confirmed = Confirmado.
page-tour-differs = Difere.
page-tour-pending = Verificando…
page-copied = Copiado
page-copy-manual = Selecione e copie (Ctrl+C)
page-share-title = Compartilhar ou incorporar “{ $title }”
page-embed-view = {" "}Visualização incorporada (sem cabeçalho do site)
page-autoplay = {" "}Iniciar a animação
page-theme = Tema{" "}
page-width = {" "}Largura{" "}
page-height = {" "}Altura{" "}
page-sliders-shown = Controles deslizantes exibidos
page-sliders-locked = Controles deslizantes bloqueados
page-plots-shown = Gráficos exibidos
page-link = Link
page-embed-code = Código de incorporação
page-preview = Prévia da demonstração incorporada
page-close = Fechar
page-language = Idioma
page-language-nav = Idioma
page-demos-nav = Demonstrações
page-no-script = O Zeta Lab precisa de JavaScript e WebAssembly.
page-catalogue-failed = Não foi possível carregar o catálogo { $name } ({ $text }); a página continua em inglês.
page-provisional = { $value } (provisório)
page-study-progress = Calculando o resultado completo
page-readouts-shown = Resultados exibidos
page-state-token = Código de estado
page-theme-auto = automático
page-theme-light = claro
page-theme-dark = escuro
page-theme-projector = projetor (alto contraste)
page-share-visitor-language = idioma do visitante
page-share-language = {" "}Idioma{" "}
page-share-fullscreen = {" "}Botão de tela cheia
page-share-ranges = Faixas e passos dos controles deslizantes (deixe vazio para manter os declarados)
page-share-col-slider = controle
page-share-col-from = de
page-share-col-to = até
page-share-col-step = passo
page-share-range-from = { $label }: mínimo
page-share-range-to = { $label }: máximo
page-share-range-step = { $label }: passo
page-share-predict-task = Tarefa de previsão
page-share-none = nenhuma
page-share-predict = Os alunos preveem{" "}
page-share-predict-within = {" "}com tolerância{" "}
page-share-presets = Predefinições do professor (incluídas no link)
page-share-preset-example = p. ex. Amortecimento leve
page-share-preset-add = Adicionar os valores da tela
page-share-preset-format = Formato: nome:chave=valor,chave=valor; outro nome:…
page-share-preset-default = Predefinição { $n }
page-share-preset-name = Nome{" "}
page-share-preset-list = Predefinições{" "}
page-lecturer-presets = Predefinições do professor
page-full-screen = Tela cheia
page-exit-full-screen = Sair da tela cheia
page-no-stamp = Este arquivo não contém nenhuma visualização do Zeta Lab (só os PNG, SVG e CSV exportados pelo Zeta Lab contêm).
page-token-invalid = Esta visualização salva não é um código de estado do Zeta Lab.
page-token-version = Esta visualização salva tem a versão de formato “{ $version }”, que esta página não consegue ler; nada foi alterado.
page-token-damaged = Esta visualização salva está danificada e não pode ser lida; nada foi alterado.
page-token-no-demo = Esta visualização salva indica uma demonstração que esta página não tem (“{ $demo }”); nada foi alterado.
page-token-other-version-missing = Esta visualização salva vem de outra versão do Zeta Lab: { $n ->
        [one] { $missing } não consta nela e começa no valor padrão.
       *[other] { $missing } não constam nela e começam no valor padrão.
    }
page-token-other-version-unknown = Esta visualização salva vem de outra versão do Zeta Lab: { $m ->
        [one] { $unknown } não é conhecido aqui e foi ignorado.
       *[other] { $unknown } não são conhecidos aqui e foram ignorados.
    }
page-token-other-version-both = Esta visualização salva vem de outra versão do Zeta Lab: { $n ->
        [one] { $missing } não consta nela e começa no valor padrão
       *[other] { $missing } não constam nela e começam no valor padrão
    }; { $m ->
        [one] { $unknown } não é conhecido aqui e foi ignorado.
       *[other] { $unknown } não são conhecidos aqui e foram ignorados.
    }
page-predict-title = Primeiro, preveja
page-predict-hint = Os gráficos e “{ $label }” ficam ocultos até você fazer sua previsão. Digite-a e pressione Enter.
page-predict-field = Sua previsão de “{ $label }”
page-predict-field-unit = Sua previsão de “{ $label }” ({ $unit })
page-predict-reveal = Revelar
page-predict-nan = “{ $text }” não é um número. Digite um número como { $example }.
page-predict-undefined = “{ $label }” não está definido para estes parâmetros; altere-os e tente novamente.
page-predict-result-inside = Você previu { $p }; “{ $label }” vale { $v }: { $how }, dentro da tolerância de { $tol }.
page-predict-result-outside = Você previu { $p }; “{ $label }” vale { $v }: { $how }, fora da tolerância de { $tol }.
page-predict-exact = exatamente certo
page-predict-high = { $d } acima
page-predict-low = { $d } abaixo

## Gráficos

plot-clipped = cortado: alguns valores ficam além dos eixos

## Palavras compartilhadas: eixos, regimes

axis-time = tempo t
axis-displacement = deslocamento x
axis-extension = alongamento x
axis-force = força F
axis-velocity = velocidade v
axis-real-part = parte real Re s
axis-imaginary-part = parte imaginária Im s
regime-undamped = não amortecido
regime-underdamped = subamortecido
regime-critically-damped = criticamente amortecido
regime-overdamped = superamortecido
regime-negatively-damped = amortecimento negativo
regime-neutral = neutro
regime-divergent = divergente

## Demonstrações

## O guia para professores (docs/embedding.md e docs/parameters.<tag>.md)

guide-parameters-heading = Parâmetros de cada demonstração
guide-parameters-note = Os parâmetros de URL de cada demonstração, para links e incorporação (veja o guia, docs/embedding.md, em inglês). Gerado a partir das declarações em Rust e do catálogo deste idioma; um teste falha se esta lista e o código divergirem.
guide-column-key = chave
guide-column-quantity = grandeza
guide-column-unit = unidade
guide-column-range = intervalo
guide-column-default = padrão
guide-log = logarítmico
guide-readouts-plots = Resultados (`data-readout`): { $readouts }. Gráficos (`plots=`): { $plots }.

### design

design-map-title = { $metric ->
        [settling-time] Acomodação em ±{ $band } de x₀
        [peak-rebound] Ressalto máximo (% de x₀)
        [accel-rms] a_w (W_k)
       *[peak-transmissibility] Transmissibilidade máxima |X/U|
    }: { $low } → { $high }
design-bar-label = { $metric ->
        [settling-time] tempo de acomodação em ±{ $band } de x₀ [s]
        [peak-rebound] ressalto máximo [% de x₀]
        [accel-rms] a_w (RMS ponderado por W_k) [m/s²]
       *[peak-transmissibility] transmissibilidade máxima |X/U| [m/m]
    }{ $scale ->
        [log] , escala log.
       *[linear] {""}
    }
design-axis-spring-rate = rigidez da mola k
design-axis-damper-rate = coeficiente do amortecedor c
design-axis-settling-time = tempo de acomodação em ±{ $band } de x₀
design-axis-comfort = a_w (RMS ponderado por W_k)
design-marker-selected = escolhido
design-marker-settled = acomodado
design-series-column = k = { $k }, c variável
design-series-pareto-front = fronteira de Pareto
design-series-band = faixa de acomodação ±{ $band } de x₀
design-series-fastest = o mais rápido da malha
design-series-selected = ajuste escolhido
design-road = uma pista ISO 8608 de classe { $class } a { $speed }
design-with-road = { $value } (pista de classe { $class }, { $speed })
design-grid-size = { $n } × { $n } = { $cells }
design-grid-size-provisional = { $n } × { $n } = { $cells } ({ $full } × { $full } a caminho)
design-map-lowest = mínimo de { $value } em k = { $k }, c = { $c }
design-map-no-cell = nenhuma célula está definida
design-map-selected-settles = o ajuste escolhido (ζ = { $zeta }) acomoda-se em ±{ $band } de x₀ em { $time }
design-map-selected-unsettled = o ajuste escolhido (ζ = { $zeta }) não se acomoda
design-map-no-selection = nenhum ajuste válido escolhido
design-describe-map = { $metric ->
        [settling-time] Tempo de acomodação da resposta livre a partir de x₀ = { $x0 } em ±{ $band } de x₀,
        [peak-rebound] Ressalto máximo da resposta livre a partir de x₀ = { $x0 }, em % de x₀,
        [accel-rms] Conforto a_w (aceleração RMS da carroceria ponderada por W_k) do veículo com dois graus de liberdade (roda de { $wheel }, pneu de { $tyre }), em regime estacionário sobre { $road },
       *[peak-transmissibility] Transmissibilidade máxima |X/U|
    } para k em { $k_span } e c em { $c_span } (malha de { $grid } × { $grid }, m = { $mass }): { $lowest }; { $selected }{ $outside ->
        [yes] {" "}(fora do mapa)
       *[no] {""}
    }. Cores do roxo escuro ({ $low }) ao amarelo ({ $high }){ $scale ->
        [log] {" "}em escala logarítmica
       *[linear] {""}
    }. Linhas tracejadas de ζ constante para ζ = { $z1 }; { $z2 }; { $z3 }; { $z4 } e { $z5 }; × marca a célula mínima e ●, o ajuste escolhido.
design-describe-pareto = Fronteira de Pareto com { $count ->
        [one] { $count } ajuste não dominado
       *[other] { $count } ajustes não dominados
    }: do mais rápido, que se acomoda em ±{ $band } de x₀ em { $fast_time } com a_w = { $fast_accel }, ao mais confortável, { $smooth_time } com a_w = { $smooth_accel }. { $selected } Conforto a_w: aceleração RMS da carroceria ponderada por W_k, do veículo com dois graus de liberdade sobre { $road }.
design-pareto-selected = O ajuste escolhido acomoda-se em ±{ $band } de x₀ em { $time } com a_w = { $accel }.
design-pareto-selected-unsettled = O ajuste escolhido não tem tempo de acomodação.
design-pareto-empty = Nenhum ajuste da malha tem ao mesmo tempo um tempo de acomodação e um valor de conforto a_w.
design-describe-response = Ajuste escolhido (ζ = { $zeta }) solto a partir do repouso em x₀ = { $x0 } (resposta livre, não ao degrau): ressalta { $rebound } de x₀ e fica dentro de ±{ $band } de x₀ após { $time }.
design-describe-response-fastest = Ajuste escolhido (ζ = { $zeta }) solto a partir do repouso em x₀ = { $x0 } (resposta livre, não ao degrau): ressalta { $rebound } de x₀ e fica dentro de ±{ $band } de x₀ após { $time }; o ajuste mais rápido da malha (k = { $k }, c = { $c }) acomoda-se em { $fastest_time }.
design-response-unsettled = O ajuste escolhido não se acomoda.
design-provisional = Provisório: a partir de uma malha grossa de { $coarse } × { $coarse } enquanto a varredura de { $full } × { $full } é calculada. { $description }
design-title = Espaço de projeto (k, c)
design-summary = Cada célula do mapa é um quarto de veículo (massa suspensa m sobre uma mola k e um amortecedor c), colorida pela métrica escolhida: tempo de acomodação e ressalto máximo da resposta livre, solta a partir do repouso em x₀ = 60 mm (não é uma resposta ao degrau: a faixa e o ressalto são relativos a x₀), transmissibilidade máxima, ou o conforto de rodagem como a ISO 2631-1 o mede: a_w, a aceleração RMS da carroceria ponderada pelo filtro W_k (o quanto uma pessoa sentada sente cada frequência), em regime estacionário sobre uma pista aleatória ISO 8608 à velocidade V. Para o conforto, cada célula é o veículo com dois graus de liberdade (esta carroceria sobre a roda m_u e o pneu k_t definidos abaixo, pela equação de Lyapunov): os mesmos números da demo quarter-car-2dof para o mesmo veículo; os resultados também dão o valor RMS sem ponderação. As linhas tracejadas ligam ajustes de mesma razão de amortecimento ζ = c/(2√(km)). A fronteira de Pareto reúne os ajustes que nenhum outro supera ao mesmo tempo em conforto e em acomodação. Clique no mapa (ou num ponto da fronteira) para escolher um ajuste; mova a massa para ver o mapa inteiro se deslocar.
design-param-m = massa suspensa
design-param-mu = conforto: massa da roda (não suspensa)
design-param-kt = conforto: rigidez do pneu
design-param-metric = métrica do mapa
design-param-metric-settling-time = tempo de acomodação (resposta livre)
design-param-metric-peak-rebound = ressalto máximo (resposta livre)
design-param-metric-accel-rms = conforto a_w (aceleração RMS da carroceria ponderada por W_k)
design-param-metric-peak-transmissibility = transmissibilidade máxima |X/U|
design-param-band = faixa de acomodação, ± % de x₀ (resposta livre)
design-param-road = pista (ISO 8608)
design-param-road-a = classe A (muito boa)
design-param-road-b = classe B (boa)
design-param-road-c = classe C (média)
design-param-road-d = classe D (ruim)
design-param-V = conforto: velocidade
design-param-k-min = mapa: menor rigidez da mola
design-param-k-max = mapa: maior rigidez da mola
design-param-c-min = mapa: menor coeficiente do amortecedor
design-param-c-max = mapa: maior coeficiente do amortecedor
design-param-k = rigidez da mola escolhida
design-param-c = coeficiente do amortecedor escolhido
design-param-n = células da malha por eixo
design-readout-k = rigidez da mola escolhida k
design-readout-c = coeficiente do amortecedor escolhido c
design-readout-zeta = razão de amortecimento ζ
design-readout-settling-time = tempo de acomodação na faixa ± de x₀ (resposta livre)
design-readout-overshoot = ressalto máximo, % de x₀ (resposta livre)
design-readout-accel-rms = a_w: aceleração RMS da carroceria ponderada pelo W_k da ISO 2631-1 (veículo com dois graus de liberdade, em regime estacionário sobre a pista ISO 8608 à velocidade V)
design-readout-accel-unweighted = aceleração RMS da carroceria, sem ponderação (mesmo veículo e mesma pista)
design-readout-grid-size = tamanho da malha (células)
design-readout-compute-time = tempo de cálculo da varredura
design-plot-map = Métrica sobre (k, c) com linhas de ζ constante
design-plot-pareto = Conforto versus acomodação: fronteira de Pareto
design-plot-response = Ajuste escolhido: resposta livre x(t)
design-preset-1 = Mapa do tempo de acomodação, 300 kg, ζ ≈ 0,37
design-preset-2 = Veículo carregado com 500 kg, mesmas peças
design-preset-3 = Mapa de conforto numa pista de classe C
design-preset-4 = Mapa do ressalto máximo, ajuste com ζ = 0,7
design-preset-5 = Malha fina de 160 × 160

## Avisos (um valor de parâmetro que não pôde ser usado)

notice-value = { $problem ->
        [toggle] { $label } ({ $key }): “{ $value }” não é ligado nem desligado; usando o padrão.
        [option] { $label } ({ $key }): “{ $value }” não é nenhuma de { $options }; usando o padrão.
        [number] { $label } ({ $key }): “{ $value }” não é um número; usando o padrão { $default }.
        [range-empty] { $label } ({ $key }): o intervalo “{ $value }” fica vazio dentro de { $min } … { $max }; mantendo o intervalo completo.
        [range-not-two-numbers] { $label } ({ $key }): o intervalo “{ $value }” não são dois números “mín,máx”; mantendo o intervalo completo.
        [step] { $label } ({ $key }): o passo “{ $value }” não é um número entre 0 e { $span }; mantendo { $step }.
       *[range] { $label } ({ $key }) = { $value } está fora de { $min } … { $max }{ $unit }; usando { $used }.
    }

## Arquivos exportados

export-csv-heading = Zeta Lab, demonstração { $demo }: { $title }
export-series = série { $n }

