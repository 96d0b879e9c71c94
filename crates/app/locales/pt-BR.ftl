### rlc

rlc-axis-current = corrente i
rlc-axis-voltage = tensão no capacitor v_C
rlc-envelope = envoltória
rlc-series-critical = R crítica = { $resistance }
rlc-schematic = Circuito RLC série em t = { $time }: corrente { $current }, capacitor em { $voltage }.
rlc-describe-current-undamped = R = { $resistance }, não amortecido (um circuito LC sem perdas): a corrente oscila indefinidamente em ω₀ = { $frequency }, entre ±{ $bound } (toda a energia passa para o indutor e volta a cada meio período).
rlc-describe-voltage-undamped = R = { $resistance }, não amortecido (um circuito LC sem perdas): a tensão no capacitor oscila indefinidamente entre +{ $voltage } e −{ $voltage } em ω₀ = { $frequency }.
rlc-describe-current-underdamped = R = { $resistance }, abaixo da resistência crítica { $critical }, subamortecido: a corrente oscila em ω_d = { $frequency } (Q = { $q }), decaindo como e^(−αt) com α = { $alpha }; nunca ultrapassa { $bound }.
rlc-describe-voltage-underdamped = R = { $resistance }, abaixo da resistência crítica { $critical }, subamortecido: a tensão no capacitor { $reversal ->
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
rlc-describe-current-critical = R = { $resistance }, igual à resistência crítica, criticamente amortecido: um único pulso de corrente (negativo, com o capacitor se descarregando) que volta a zero sem inverter; a corrente nunca ultrapassa { $bound }.
rlc-describe-voltage-critical = R = { $resistance }, igual à resistência crítica, criticamente amortecido: o capacitor se descarrega o mais rápido possível sem inverter; a tensão { $settles ->
        [yes] fica dentro de 5 % de V₀ após { $time }
       *[no] nunca se acomoda
    }.
rlc-describe-current-overdamped = R = { $resistance }, acima da resistência crítica { $critical }, superamortecido: um pulso lento de corrente (negativo, com o capacitor se descarregando) sem inverter, constante de tempo lenta { $time }.
rlc-describe-voltage-overdamped = R = { $resistance }, acima da resistência crítica { $critical }, superamortecido: o capacitor se descarrega lentamente sem inverter; a tensão { $settles ->
        [yes] fica dentro de 5 % de V₀ após { $time }
       *[no] nunca se acomoda
    }.
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

